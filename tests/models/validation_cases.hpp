#pragma once
// Shared by the model tests: one validation case per rule, and the message a call throws.

#include <functional>
#include <stdexcept>
#include <string>

#include "error_message.hpp"

namespace frictionlab::testing {

/// A rule of a law: its name (for the test's name), a call that breaks it, the exact message.
struct RuleCase {
  std::string name;
  std::function<void()> validate;
  std::string message;
};

/// A call that validates a default `Law` after `edit` changed it.
template <class Law, class Edit>
std::function<void()> with(Edit edit) {
  return [edit] {
    Law law{};
    edit(law);
    law.validate();
  };
}

}  // namespace frictionlab::testing
