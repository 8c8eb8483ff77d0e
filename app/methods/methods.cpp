// The registry of the command line's identification methods: FRICTIONLAB_METHODS (identify/method.hpp)
// pairs each method's library side with its NAME_method(); and the flags made from a method's
// option table.
#include <memory>
#include <sstream>

#include "frictionlab/identify/option_applies.hpp"
#include "method.hpp"

namespace frictionlab::cli {

const std::vector<CliMethod>& cli_methods() {
  static const std::vector<CliMethod> methods = [] {
    std::vector<CliMethod> all;
#define FRICTIONLAB_CLI_METHOD(method)             \
  all.push_back(method##_method());                \
  all.back().info = &method_info(MethodId::FRICTIONLAB_METHOD_ENUM(method)); \
  all.back().name = all.back().info->name;
    FRICTIONLAB_METHODS(FRICTIONLAB_CLI_METHOD)
#undef FRICTIONLAB_CLI_METHOD
    return all;
  }();
  return methods;
}

const CliMethod* find_cli_method(const std::string& name) {
  for (const auto& m : cli_methods())
    if (m.name == name) return &m;
  return nullptr;
}

namespace {

// The help of one option of `table`: its text, then (unit; default; valid values; when it applies).
std::string option_help(const OptionSpec& o, const std::vector<OptionSpec>& table) {
  std::ostringstream s;
  s << o.help;
  std::vector<std::string> notes;
  if (!o.unit_text().empty()) notes.push_back(o.unit_text());
  if (o.default_value && o.type != OptionType::flag) notes.push_back("default " + option_text(*o.default_value));
  if (o.type == OptionType::number || o.type == OptionType::integer) {
    const std::string rule = o.rule();
    if (!rule.empty()) notes.push_back(rule);
  }
  if (o.type == OptionType::text && !o.words.empty()) notes.push_back(o.expected());
  const std::string applies = applies_text(o, table);
  if (!applies.empty()) notes.push_back(applies);
  if (!notes.empty()) {
    s << " (";
    for (std::size_t i = 0; i < notes.size(); ++i) s << (i ? "; " : "") << notes[i];
    s << ")";
  }
  return s.str();
}

const char* type_name(const OptionSpec& o) {
  switch (o.type) {
    case OptionType::number: return o.words.empty() ? "NUMBER" : "NUMBER|WORD";
    case OptionType::integer: return "INT";
    case OptionType::list: return o.repeatable ? "TEXT" : "A,B,...";
    case OptionType::column: return "COLUMN";
    case OptionType::file: return "FILE";
    default: return "TEXT";
  }
}

}  // namespace

GivenOptions add_table_options(CLI::App* cmd, const MethodInfo& info) {
  struct Flag {
    const OptionSpec* spec;
    CLI::Option* opt;
    std::shared_ptr<std::vector<std::string>> texts = std::make_shared<std::vector<std::string>>();  // repeatable
    std::shared_ptr<std::string> text = std::make_shared<std::string>();  // one value
    std::shared_ptr<bool> on = std::make_shared<bool>(false);
  };
  auto flags = std::make_shared<std::vector<Flag>>();
  for (const OptionSpec& o : info.options) {
    Flag f{&o, nullptr};
    const std::string name = "--" + o.name;
    if (o.type == OptionType::flag) {
      f.opt = cmd->add_flag(name, *f.on, option_help(o, info.options));
    } else if (o.repeatable) {
      f.opt = cmd->add_option(name, *f.texts, option_help(o, info.options))->type_name(type_name(o));
    } else {
      f.opt = cmd->add_option(name, *f.text, option_help(o, info.options))->type_name(type_name(o));
    }
    if (o.required) f.opt->required();
    flags->push_back(f);
  }
  return [flags, &info]() {
    OptionValues values = info.values();
    for (const Flag& f : *flags) {
      if (f.opt->count() == 0) continue;
      const std::string spelled = "--" + f.spec->name;
      if (f.spec->type == OptionType::flag) values.set(f.spec->name, *f.on, spelled);
      else if (!f.spec->repeatable) values.set(f.spec->name, parse_option(*f.spec, *f.text, spelled), spelled);
      else
        for (const std::string& text : *f.texts) values.set(f.spec->name, parse_option(*f.spec, text, spelled), spelled);
    }
    return values;
  };
}

void record_options(Result& r, const OptionValues& options) {
  r.json_sections["options"] = options_json(options, r.axis == Axis::rotary, r.diagnostics.texts);
}

}  // namespace frictionlab::cli
