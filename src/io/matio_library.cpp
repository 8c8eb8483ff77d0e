#include "matio_library.hpp"

#include <dlfcn.h>

#include <stdexcept>
#include <string>
#include <type_traits>

namespace frictionlab::detail {
namespace {

MatioLibrary load() {
  void* handle = dlopen(FRICTIONLAB_MATIO_SONAME, RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error(std::string("reading MAT files needs the matio library (" FRICTIONLAB_MATIO_SONAME
                                         "), which could not be loaded: ") +
                             (why != nullptr ? why : "unknown reason") +
                             "; install it (Debian: libmatio11, or run scripts/setup.sh) or convert the file to CSV");
  }
  // Kept loaded for the life of the process: the functions are used from any thread.
  MatioLibrary m{};
  const auto bind = [&](auto& fn, const char* name) {
    dlerror();
    void* symbol = dlsym(handle, name);
    if (symbol == nullptr)
      throw std::runtime_error(std::string(FRICTIONLAB_MATIO_SONAME " has no function ") + name +
                               "; expected matio 1.5 (the version frictionlab was built with: " MATIO_VERSION_STR ")");
    fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(symbol);
  };
  bind(m.LogInitFunc, "Mat_LogInitFunc");
  bind(m.Open, "Mat_Open");
  bind(m.Close, "Mat_Close");
  bind(m.Rewind, "Mat_Rewind");
  bind(m.GetVersion, "Mat_GetVersion");
  bind(m.SizeOfClass, "Mat_SizeOfClass");
  bind(m.VarReadNextInfo, "Mat_VarReadNextInfo");
  bind(m.VarReadNext, "Mat_VarReadNext");
  bind(m.VarFree, "Mat_VarFree");
  bind(m.VarGetNumberOfFields, "Mat_VarGetNumberOfFields");
  bind(m.VarGetStructFieldnames, "Mat_VarGetStructFieldnames");
  return m;
}

}  // namespace

const MatioLibrary& matio_library() {
  static const MatioLibrary m = load();  // a failed load throws and is retried on the next call
  return m;
}

}  // namespace frictionlab::detail
