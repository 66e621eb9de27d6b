// The model readers' module (docs/design.md, "Models"): STEP and IGES (Open CASCADE), glTF 2
// (tinygltf) and 3MF (lib3mf) are read in a shared module, libhlr_models.so, loaded the first
// time a model is read. A program that reads no model never loads those libraries and their
// sixty dependencies (their relocations alone took 85 ms at every start). This header is the
// interface between the two sides: one C entry point taking a call record, the readers behind
// it, and where the loader looks for the module.
#pragma once

#include <string>
#include <vector>

#include "io/models/model.hpp"

namespace hlr {

/// Changes whenever ModelReadCall or Model changes: a module of another build is refused.
constexpr int kModelModuleAbi = 1;

enum class ModelFormat { Cad, Gltf, ThreeMf };

/// One read through the module: the request in, the model or the error out (errors do not
/// cross the boundary as exceptions; the loader throws them again as InputError,
/// std::invalid_argument or std::runtime_error).
struct ModelReadCall {
  ModelFormat format = ModelFormat::Cad;
  std::string path;
  TessellationOptions tessellation;
  Model model;
  enum class Error { None, Input, Argument, Other } error = Error::None;
  std::string message, file;  // Input: InputError's file, line and message; else what()
  int line = 0;
};

/// What both sides compile in and compare: the ABI number and the records' sizes, so a module
/// whose Model differs in layout is refused even where the number was not changed.
constexpr long model_module_abi() { return kModelModuleAbi * 1000000L + static_cast<long>(sizeof(ModelReadCall) * 1000 + sizeof(ModelBody)); }

/// The lower-case extension of a path, with its dot (".step").
std::string lower_extension(const std::string& path);

/// Reads a model through the module, loading it on first use (thread-safe). Throws InputError
/// (bad file, or no module found: the message names the places looked at).
Model read_with_module(ModelFormat format, const std::string& path, const TessellationOptions& tessellation = {});

/// Where the loader looks for libhlr_models.so: $HLR_MODELS_MODULE alone when set; else, in
/// order, the folder of the program or library holding this code, its ../LIBDIR/exact-hlr and a
/// wheel's ../lib/python3.*/site-packages/exact_hlr; the build tree; the install prefix's
/// LIBDIR/exact-hlr.
std::vector<std::string> model_module_candidates();

/// The readers, compiled into the module only (cad_reader.cpp, gltf_reader.cpp,
/// threemf_reader.cpp).
namespace models {
Model read_cad(const std::string& path, const TessellationOptions& options);
Model read_gltf(const std::string& path);
Model read_3mf(const std::string& path);
}  // namespace models

}  // namespace hlr

extern "C" {
/// The module's entry points: its ABI number, and one read.
long hlr_models_abi();
void hlr_models_read(hlr::ModelReadCall* call);
}
