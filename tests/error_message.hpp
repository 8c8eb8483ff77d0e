#pragma once
// Shared by the tests of every layer: the message a call reports as bad input.

#include <stdexcept>
#include <string>

namespace frictionlab::testing {

/// The what() of the std::invalid_argument that `f()` throws, or a marker when it throws none
/// (so a missing error fails the comparison with the expected message, visibly).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "<no std::invalid_argument>";
}

}  // namespace frictionlab::testing
