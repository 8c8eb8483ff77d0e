// frictionlab help [--markdown] [-o FILE]: the options reference of the identification methods,
// made from the option tables of the library (identify/method.hpp), as the flags of
// `frictionlab identify METHOD --help` are.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "frictionlab/identify/method.hpp"
#include "frictionlab/identify/option_applies.hpp"
#include "io/atomic_write.hpp"
#include "output.hpp"

namespace frictionlab::cli {

namespace {

struct HelpArgs {
  bool markdown = false;
  bool commands = false;
  std::string out;
  bool overwrite = false;
};

// One line per option: "  --NAME (TYPE, UNIT) default D: HELP (applies with --X)".
std::string options_text() {
  std::string s;
  for (const auto& m : identification_methods()) {
    s += m.name + ": " + m.summary + "\n";
    for (const auto& o : m.options) {
      s += "  --" + o.name + " (" + to_string(o.type) + (o.unit_text().empty() ? "" : ", " + o.unit_text()) + ")";
      if (o.required) s += " required";
      else if (o.default_value) s += " default " + option_text(*o.default_value);
      s += ": " + o.help;
      const std::string applies = applies_text(o, m.options);
      if (!applies.empty()) s += " (" + applies + ")";
      s += "\n";
    }
  }
  return s;
}

}  // namespace

Handler register_help(CLI::App& app) {
  auto a = std::make_shared<HelpArgs>();
  auto* cmd = app.add_subcommand("help", "The options of every identification method, from their option tables "
                                         "(--markdown: the options reference as Markdown)");
  cmd->add_flag("--markdown", a->markdown, "Write the reference as Markdown (a heading and a table per method)");
  cmd->add_flag("--commands", a->commands,
                "Write every command with its positional arguments and options as JSON instead, output options "
                "marked (\"output\": file, figure or report)");
  output_option(cmd->add_option("-o,--output", a->out, "Write to FILE instead of stdout"));
  cmd->add_flag("--overwrite", a->overwrite, "Replace an existing FILE");
  const CLI::App* root = &app;
  return [a, root]() -> int {
    const std::string text = a->commands ? commands_json(*root) + "\n" : a->markdown ? options_markdown() : options_text();
    if (a->out.empty()) {
      std::cout << text;
      return 0;
    }
    check_run_files({}, {{"--output", a->out, RunFile::Kind::file}}, a->overwrite);
    AtomicWriteOptions w;
    w.overwrite = a->overwrite;
    write_file_atomic(a->out, text, w);
    return 0;
  };
}

}  // namespace frictionlab::cli
