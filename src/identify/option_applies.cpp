#include "frictionlab/identify/option_applies.hpp"

#include <stdexcept>

namespace frictionlab {

std::string applies_text(const OptionSpec& spec, const std::vector<OptionSpec>& table, bool markdown) {
  const auto code = [markdown](const std::string& s) { return markdown ? "`" + s + "`" : s; };
  std::string text;
  for (const OptionCondition& c : spec.applies_if) {
    const OptionSpec* other = nullptr;
    for (const OptionSpec& o : table)
      if (o.name == c.option) other = &o;
    if (!other)
      throw std::invalid_argument("--" + spec.name + ": its condition names --" + c.option +
                                  ", which is not an option of the table");
    const std::string flag = code("--" + c.option);
    std::string part;
    if (c.words.empty()) {
      part = (c.negated ? "without " : "with ") + flag;
    } else {
      // "a", "a or b", "a, b or c"
      std::string words;
      for (std::size_t i = 0; i < c.words.size(); ++i)
        words += (i == 0 ? "" : i + 1 == c.words.size() ? " or " : ", ") + code(c.words[i]);
      const bool list = other->type == OptionType::list;
      part = "when " + flag + (list ? (c.negated ? " does not hold " : " holds ") : (c.negated ? " is not " : " is ")) +
             words;
    }
    text += (text.empty() ? "applies " : " and ") + part;
  }
  return text;
}

}  // namespace frictionlab
