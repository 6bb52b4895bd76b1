// lensrt: render glTF scenes through real camera optics.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "app/command.h"
#include "core/error.h"

namespace {

std::string joinCommandLine(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) {
    if (i) s += ' ';
    const std::string arg = argv[i];
    const bool quote = arg.empty() || arg.find_first_of(" \t\"'") != std::string::npos;
    s += quote ? "'" + arg + "'" : arg;
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "lensrt: a path tracer that renders glTF scenes through real camera optics.\n"
      "Example: lensrt render scenes/dof_row.gltf --spp 64 -o out/dof_row.exr",
      "lensrt"};
  app.set_version_flag("--version", std::string(LENSRT_VERSION));
  app.require_subcommand(1);
  const lensrt::CommandContext context{joinCommandLine(argc, argv)};

  std::vector<std::pair<const CLI::App*, lensrt::CommandAction>> commands;
  const auto add = [&](auto registerFn) {
    const std::size_t before = app.get_subcommands({}).size();
    lensrt::CommandAction action = registerFn(app, context);
    commands.emplace_back(app.get_subcommands({}).at(before), std::move(action));
  };
  add(lensrt::addRenderCommand);
  add(lensrt::addLensCommand);
  add(lensrt::addDiffCommand);
  add(lensrt::addCompareCommand);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "lensrt: error: {} (see lensrt --help)\n", e.what());
    return 2;
  }

  try {
    for (const auto& [sub, action] : commands)
      if (sub->parsed()) return action();
  } catch (const CLI::ParseError& e) {
    // Value checks done after parsing (units, ranges) are usage errors too.
    fmt::print(stderr, "lensrt: error: {}\n", e.what());
    return 2;
  } catch (const lensrt::InputError& e) {
    fmt::print(stderr, "lensrt: error: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "lensrt: error: {}\n", e.what());
    return 1;
  }
  return 2;
}
