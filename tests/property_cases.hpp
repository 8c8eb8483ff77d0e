#pragma once
// The number of cases of a seeded property test: FRICTIONLAB_PROPERTY_CASES when set to a positive
// integer, else 1000 (docs/developers.md).

#include <cstdlib>

namespace frictionlab::testing {

inline int property_cases() {
  if (const char* text = std::getenv("FRICTIONLAB_PROPERTY_CASES")) {
    const int n = std::atoi(text);
    if (n > 0) return n;
  }
  return 1000;
}

}  // namespace frictionlab::testing
