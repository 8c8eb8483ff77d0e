#include "frictionlab/identify/option_applies.hpp"

#include <stdexcept>

namespace frictionlab {

std::string applies_text(const OptionSpec& spec, const std::vector<OptionSpec>& table, AppliesStyle style) {
  const bool python = style == AppliesStyle::python;
  const auto code = [style](const std::string& s) { return style == AppliesStyle::markdown ? "`" + s + "`" : s; };
  // A word is a Python string in a docstring ('stribeck'), as the keyword takes it.
  const auto word = [&code, python](const std::string& s) { return python ? "'" + s + "'" : code(s); };
  std::string text;
  for (const OptionCondition& c : spec.applies_if) {
    const OptionSpec* other = nullptr;
    for (const OptionSpec& o : table)
      if (o.name == c.option) other = &o;
    if (!other)
      throw std::invalid_argument("--" + spec.name + ": its condition names --" + c.option +
                                  ", which is not an option of the table");
    const std::string flag = python ? other->keyword() : code("--" + c.option);
    std::string part;
    if (c.words.empty() && python) {
      // A flag is True or False; any other option is given or not (None).
      part = other->type == OptionType::flag ? "with " + flag + (c.negated ? "=False" : "=True")
                                             : "when " + flag + (c.negated ? " is not given" : " is given");
    } else if (c.words.empty()) {
      part = (c.negated ? "without " : "with ") + flag;
    } else {
      // "a", "a or b", "a, b or c"
      std::string words;
      for (std::size_t i = 0; i < c.words.size(); ++i)
        words += (i == 0 ? "" : i + 1 == c.words.size() ? " or " : ", ") + word(c.words[i]);
      const bool list = other->type == OptionType::list;
      part = "when " + flag + (list ? (c.negated ? " does not hold " : " holds ") : (c.negated ? " is not " : " is ")) +
             words;
    }
    text += (text.empty() ? "applies " : " and ") + part;
  }
  return text;
}

}  // namespace frictionlab
