#include "app/option_flags.h"

#include <fmt/core.h>

#include <algorithm>

#include "core/error.h"

namespace lensrt {
namespace {

// A CLI11 check running the row's parser on a scratch spec.
CLI::Validator rowCheck(const Option& row) {
  return CLI::Validator(
      [&row](std::string& text) -> std::string {
        RenderSpec scratch;
        try {
          row.set(scratch, text);
          return "";
        } catch (const UsageError& e) {
          return e.message();
        }
      },
      row.valueName);
}

}  // namespace

OptionFlags::OptionFlags(CLI::App& app, RenderSpec& spec, unsigned command,
                         const std::vector<std::string>& groups)
    : command_(command) {
  for (const Option& row : optionTable()) {
    if (!(row.commands & command)) continue;
    if (!groups.empty() && std::find(groups.begin(), groups.end(), row.group) == groups.end()) continue;
    CLI::Option* option = nullptr;
    if (row.isFlag) {
      option = app.add_flag_function(
          row.flag, [&spec, &row](std::int64_t count) { row.set(spec, count > 0 ? "1" : "0"); }, row.help);
      if (!row.environmentVariable.empty())
        option->envname(row.environmentVariable)
            ->check(CLI::Validator(
                [&row](std::string& text) -> std::string {
                  try {
                    CLI::detail::to_flag_value(text);
                    return "";
                  } catch (const std::exception&) {
                    return "expected 1 (on) or 0 (off), e.g. " + row.environmentVariable + "=1, got '" +
                           text + "'";
                  }
                },
                ""));
    } else if (row.repeatable) {
      option = app.add_option_function<std::vector<std::string>>(
                      row.flag,
                      [&spec, &row](const std::vector<std::string>& values) {
                        for (const std::string& v : values) row.set(spec, v);
                      },
                      row.help)
                   ->delimiter(',')
                   ->check(rowCheck(row));
    } else {
      option = app.add_option_function<std::string>(
                      row.flag, [&spec, &row](const std::string& text) { row.set(spec, text); }, row.help)
                   ->check(rowCheck(row));
    }
    added_.emplace_back(&row, option);
  }
}

std::vector<const Option*> OptionFlags::given() const {
  std::vector<const Option*> rows;
  for (const auto& [row, option] : added_)
    if (option->count() > 0) rows.push_back(row);
  return rows;
}

void OptionFlags::warnUnused(const RenderSpec& spec, bool quiet) const {
  if (quiet) return;
  for (const std::string& message : unusedSettings(spec, given(), command_))
    fmt::print(stderr, "lensrt: warning: {}\n", message);
}

}  // namespace lensrt
