// The loader of the model readers' module (see model_module.hpp), and the readers' public
// functions (cad_reader.hpp, gltf_reader.hpp, threemf_reader.hpp), which forward to it.
#include "io/models/model_module.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>

#include "io/models/cad_reader.hpp"
#include "io/models/gltf_reader.hpp"
#include "io/models/threemf_reader.hpp"
#include "io/readers/input_error.hpp"

namespace hlr {

namespace {

namespace fs = std::filesystem;

using ReadFunction = void (*)(ModelReadCall*);
using AbiFunction = long (*)();

// The folder of the program or shared library this code is linked into.
fs::path own_folder() {
  Dl_info info{};
  if (!dladdr(reinterpret_cast<const void*>(&own_folder), &info) || !info.dli_fname) return {};
  std::error_code ec;
  const fs::path p = fs::canonical(info.dli_fname, ec);
  return ec ? fs::path(info.dli_fname).parent_path() : p.parent_path();
}

struct Module {
  ReadFunction read = nullptr;
  std::string error;  // why none was loaded
};

Module load_module() {
  Module m;
  std::string tried;
  for (const std::string& path : model_module_candidates()) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
      tried += "\n  " + path + " (not there)";
      continue;
    }
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      tried += "\n  " + path + " (" + (why ? why : "cannot be loaded") + ")";
      continue;
    }
    const auto abi = reinterpret_cast<AbiFunction>(dlsym(handle, "hlr_models_abi"));
    const auto read = reinterpret_cast<ReadFunction>(dlsym(handle, "hlr_models_read"));
    if (!abi || !read || abi() != model_module_abi()) {
      tried += "\n  " + path + " (from another build of exact-hlr)";
      dlclose(handle);
      continue;
    }
    m.read = read;  // the module stays loaded for the process
    return m;
  }
  m.error = "reading STEP, IGES, glTF and 3MF needs exact-hlr's model module libhlr_models.so, not found:" + tried +
            "\n(set HLR_MODELS_MODULE to its path)";
  return m;
}

}  // namespace

std::string lower_extension(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

std::vector<std::string> model_module_candidates() {
  const std::string name = "libhlr_models.so";
  std::vector<std::string> out;
  if (const char* env = std::getenv("HLR_MODELS_MODULE"); env && *env) return {env};  // that one alone
  const fs::path here = own_folder();
  if (!here.empty()) {
    out.push_back((here / name).string());
    out.push_back((here / ".." / HLR_INSTALL_LIBDIR / "exact-hlr" / name).lexically_normal().string());
    std::error_code ec;
    const fs::path lib = (here / ".." / "lib").lexically_normal();
    for (fs::directory_iterator it(lib, ec), end; !ec && it != end; it.increment(ec))  // a wheel's hlr in a venv's bin
      if (it->path().filename().string().rfind("python3", 0) == 0) out.push_back((it->path() / "site-packages" / "exact_hlr" / name).string());
  }
  out.push_back(std::string(HLR_BUILD_MODULE_DIR) + "/" + name);
  out.push_back(std::string(HLR_INSTALL_FULL_LIBDIR) + "/exact-hlr/" + name);
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Model read_with_module(ModelFormat format, const std::string& path, const TessellationOptions& tessellation) {
  static std::once_flag once;
  static Module module;
  std::call_once(once, [] { module = load_module(); });
  if (!module.read) throw InputError(path, 0, module.error);
  ModelReadCall call;
  call.format = format;
  call.path = path;
  call.tessellation = tessellation;
  module.read(&call);
  switch (call.error) {
    case ModelReadCall::Error::None:
      return std::move(call.model);
    case ModelReadCall::Error::Input:
      throw InputError(call.file, call.line, call.message);
    case ModelReadCall::Error::Argument:
      throw std::invalid_argument(call.message);
    case ModelReadCall::Error::Other:
      break;
  }
  throw std::runtime_error(call.message);
}

bool is_cad_file(const std::string& path) {
  const std::string e = lower_extension(path);
  return e == ".step" || e == ".stp" || e == ".iges" || e == ".igs";
}

bool is_gltf_file(const std::string& path) {
  const std::string e = lower_extension(path);
  return e == ".gltf" || e == ".glb";
}

bool is_3mf_file(const std::string& path) { return lower_extension(path) == ".3mf"; }

Model read_cad_file(const std::string& path, const TessellationOptions& options) { return read_with_module(ModelFormat::Cad, path, options); }

Model read_gltf_file(const std::string& path) { return read_with_module(ModelFormat::Gltf, path); }

Model read_3mf_file(const std::string& path) { return read_with_module(ModelFormat::ThreeMf, path); }

}  // namespace hlr
