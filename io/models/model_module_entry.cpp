// The model readers' module's entry points (see model_module.hpp): compiled into
// libhlr_models.so only, with the readers and the libraries they need.
#include <exception>
#include <stdexcept>

#include "io/models/model_module.hpp"
#include "io/readers/input_error.hpp"

extern "C" __attribute__((visibility("default"))) long hlr_models_abi() { return hlr::model_module_abi(); }

extern "C" __attribute__((visibility("default"))) void hlr_models_read(hlr::ModelReadCall* call) {
  using hlr::ModelFormat;
  using Error = hlr::ModelReadCall::Error;
  try {
    switch (call->format) {
      case ModelFormat::Cad:
        call->model = hlr::models::read_cad(call->path, call->tessellation);
        break;
      case ModelFormat::Gltf:
        call->model = hlr::models::read_gltf(call->path);
        break;
      case ModelFormat::ThreeMf:
        call->model = hlr::models::read_3mf(call->path);
        break;
    }
  } catch (const hlr::InputError& e) {
    call->error = Error::Input, call->file = e.file(), call->line = e.line(), call->message = e.message();
  } catch (const std::invalid_argument& e) {
    call->error = Error::Argument, call->message = e.what();
  } catch (const std::exception& e) {
    call->error = Error::Other, call->message = e.what();
  } catch (...) {
    call->error = Error::Other, call->message = call->path + ": the model reader failed";
  }
}
