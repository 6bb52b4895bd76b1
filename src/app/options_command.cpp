// `lensrt options`: every render setting of the option table, for people
// (one line each) and for the docs (--markdown: docs/cli-reference.md).
#include <fmt/core.h>

#include <CLI/CLI.hpp>

#include "api/option_table.h"
#include "app/command.h"

namespace lensrt {

CommandAction addOptionsCommand(CLI::App& app, const CommandContext&) {
  CLI::App* cmd = app.add_subcommand("options",
                                     "List every render setting: its flag, Python keyword, value and help.\n"
                                     "Example: lensrt options --markdown > docs/cli-reference.md");
  auto markdown = std::make_shared<bool>(false);
  cmd->add_flag("--markdown", *markdown, "print the reference page (docs/cli-reference.md)");
  return [markdown]() {
    if (*markdown) {
      fmt::print("{}", optionReferenceMarkdown());
      return 0;
    }
    for (const Option& o : optionTable())
      fmt::print("{} {}  ({})\n    {}\n", o.flag, o.valueName,
                 o.keyword.empty() ? "command line only" : "Python " + o.keyword + "=", o.help);
    return 0;
  };
}

}  // namespace lensrt
