// lib3mf's C interface as selfsim's .3mf writer and reader use it (threemf_file.cpp, threemf_read.cpp): a
// handle released at the end of its scope, and a failed call as an Error with lib3mf's own message. lib3mf's
// header declares Windows-style types and SAL macros globally: include this only in those two files.
#pragma once

#include <Model/COM/NMR_DLLInterfaces.h>

#include <string>

#include "kernels/base/error.h"

namespace selfsim::io {

struct Lib3mfHandle {
  NMR::PLib3MFBase* p = nullptr;
  Lib3mfHandle() = default;
  Lib3mfHandle(const Lib3mfHandle&) = delete;
  Lib3mfHandle& operator=(const Lib3mfHandle&) = delete;
  ~Lib3mfHandle() {
    if (p != nullptr) NMR::lib3mf_release(p);
  }
};

// Throws Error "lib3mf could not <what>: <its message>" when a call failed.
inline void lib3mf_check(LIB3MFRESULT result, NMR::PLib3MFBase* handle, const char* what) {
  if (result == LIB3MF_OK) return;
  DWORD code = 0;
  LPCSTR message = nullptr;
  std::string reason = "error " + std::to_string(result);
  if (handle != nullptr && NMR::lib3mf_getlasterror(handle, &code, &message) == LIB3MF_OK && message != nullptr)
    reason = message;
  throw Error(std::string("lib3mf could not ") + what + ": " + reason);
}

}  // namespace selfsim::io
