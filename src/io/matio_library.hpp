// matio, loaded when the first MAT file is read rather than when the program starts.
//
// matio brings HDF5 and, through it, curl, GnuTLS, Kerberos and LDAP: about 30 shared libraries
// that every `frictionlab` run (and `import frictionlab`) would otherwise map and relocate at
// start-up, though only MAT input needs them. The functions are resolved once, by name, from the
// library whose soname the build found (FRICTIONLAB_MATIO_SONAME); their types come from
// matio.h, so a changed signature fails to compile.
#pragma once

#include <matio.h>

namespace frictionlab::detail {

struct MatioLibrary {
  decltype(&::Mat_LogInitFunc) LogInitFunc;
  decltype(&::Mat_Open) Open;
  decltype(&::Mat_Close) Close;
  decltype(&::Mat_Rewind) Rewind;
  decltype(&::Mat_GetVersion) GetVersion;
  decltype(&::Mat_SizeOfClass) SizeOfClass;
  decltype(&::Mat_VarReadNextInfo) VarReadNextInfo;
  decltype(&::Mat_VarReadNext) VarReadNext;
  decltype(&::Mat_VarFree) VarFree;
  decltype(&::Mat_VarGetNumberOfFields) VarGetNumberOfFields;
  decltype(&::Mat_VarGetStructFieldnames) VarGetStructFieldnames;
};

// The loaded library's functions; loads it on the first call (thread-safe).
// Throws std::runtime_error naming the library and the loader's message when it cannot be
// loaded or lacks a function (install the libmatio package: scripts/setup.sh).
const MatioLibrary& matio_library();

}  // namespace frictionlab::detail
