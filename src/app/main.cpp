// lensrt: render glTF scenes through real camera optics.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "app/command.h"
#include "run/mpi_job.h"
#include "core/error.h"
#include "core/leak_check.h"

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

// "lensrt render" for an error while parsing render's flags: the help that
// lists them.
std::string helpCommand(const CLI::App& app) {
  std::string command = "lensrt";
  const CLI::App* current = &app;
  while (true) {
    const auto parsed = current->get_subcommands([](const CLI::App* sub) { return sub->parsed(); });
    if (parsed.empty()) return command;
    current = parsed.front();
    command += " " + current->get_name();
  }
}

// CLI11 reports a mistyped command as "A subcommand is required"; name the
// word and the commands there are. Empty when the command words are fine.
std::string unknownCommand(const CLI::App& app, int argc, char** argv) {
  const CLI::App* current = &app;
  std::string path = "lensrt";
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    // An option (whose value may follow) ends the command words.
    if (word.empty() || word[0] == '-') break;
    const auto subs = current->get_subcommands([](const CLI::App*) { return true; });
    if (subs.empty()) break;
    const auto it =
        std::find_if(subs.begin(), subs.end(), [&](const CLI::App* s) { return s->check_name(word); });
    if (it == subs.end()) {
      std::string names;
      for (std::size_t k = 0; k < subs.size(); ++k)
        names += (k == 0 ? "" : k + 1 == subs.size() ? " or " : ", ") + subs[k]->get_name();
      return fmt::format("unknown command '{}' for {}: use {} (see {} --help)", word, path, names, path);
    }
    current = *it;
    path += " " + current->get_name();
  }
  const auto subs = current->get_subcommands([](const CLI::App*) { return true; });
  if (current->get_require_subcommand_min() > 0 && !subs.empty() &&
      std::none_of(subs.begin(), subs.end(), [](const CLI::App* s) { return s->parsed(); })) {
    std::string names;
    for (std::size_t k = 0; k < subs.size(); ++k)
      names += (k == 0 ? "" : k + 1 == subs.size() ? " or " : ", ") + subs[k]->get_name();
    return fmt::format("{} needs a command: {} (see {} --help)", path, names, path);
  }
  return "";
}

int run(int argc, char** argv) {
  CLI::App app{
      "lensrt: a path tracer that renders glTF scenes through real camera optics.\n"
      "Example: lensrt render scenes/dof_row.gltf --spp 64 -o out/dof_row.exr",
      "lensrt"};
  lensrt::MpiJob mpi(argc, argv);
  app.set_version_flag("--version", std::string(LENSRT_VERSION) +
                                        (lensrt::MpiJob::builtWithMpi() ? " (MPI: yes)" : " (MPI: no)"));
  app.require_subcommand(1);
  const lensrt::CommandContext context{joinCommandLine(argc, argv), &mpi};

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
  add(lensrt::addMergeCommand);
  add(lensrt::addSensorCommand);
  add(lensrt::addOptionsCommand);
  // `lensrt --help` lists one line per command; the rest of a command's
  // description (examples, diff's statistics) stays in its own --help, after
  // its options.
  for (CLI::App* sub : app.get_subcommands({})) {
    const std::string text = sub->get_description();
    const std::size_t newline = text.find('\n');
    if (newline == std::string::npos) continue;
    sub->description(text.substr(0, newline));
    sub->footer(text.substr(newline + 1));
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Under MPI every rank parses the same command line: rank 0 alone speaks.
    if (!mpi.isMain()) return e.get_exit_code() == 0 ? 0 : 2;
    if (dynamic_cast<const CLI::CallForHelp*>(&e) || dynamic_cast<const CLI::CallForAllHelp*>(&e) ||
        dynamic_cast<const CLI::CallForVersion*>(&e))
      return app.exit(e);
    if (const std::string unknown = unknownCommand(app, argc, argv); !unknown.empty()) {
      fmt::print(stderr, "lensrt: error: {}\n", unknown);
      return 2;
    }
    fmt::print(stderr, "lensrt: error: {} (see {} --help)\n", e.what(), helpCommand(app));
    return 2;
  }

  if (!mpi.unsupportedLaunch().empty()) {
    if (mpi.isMain()) fmt::print(stderr, "lensrt: error: {}\n", mpi.unsupportedLaunch());
    return 2;
  }
  // `render` and `compare` are shared between the ranks of an MPI job; other
  // commands run on rank 0 alone.
  const bool shared =
      mpi.size() > 1 && std::any_of(commands.begin(), commands.end(), [](const auto& command) {
        return command.first->parsed() &&
               (command.first->get_name() == "render" || command.first->get_name() == "compare");
      });
  if (mpi.size() > 1 && !shared && !mpi.isMain()) return 0;
  // One error line. In a shared render, a rank failing in its set-up (scene,
  // camera) waits for the others to get there, so that the job reports the
  // lowest failing rank's error once; after the set-up it ends the job.
  const auto fail = [&](int status, const std::string& line) {
    if (shared && !mpi.agreed()) {
      const auto failure = mpi.agree(lensrt::MpiJob::Failure{mpi.rank(), status, line});
      if (mpi.isMain())
        fmt::print(stderr, "lensrt: error: {}{}\n",
                   failure->rank == 0 ? "" : fmt::format("rank {} of {}: ", failure->rank, mpi.size()),
                   failure->line);
      return failure->status;
    }
    if (shared) {
      fmt::print(stderr, "lensrt: error: rank {} of {}: {}\n", mpi.rank(), mpi.size(), line);
      std::fflush(stderr);
      mpi.abort(status);
    }
    fmt::print(stderr, "lensrt: error: {}\n", line);
    return status;
  };
  try {
    for (const auto& [sub, action] : commands)
      if (sub->parsed()) return action();
  } catch (const CLI::ParseError& e) {
    // Value checks done after parsing (units, ranges) are usage errors too.
    return fail(2, e.what());
  } catch (const lensrt::UsageError& e) {
    return fail(2, e.what());
  } catch (const lensrt::InputError& e) {
    return fail(1, e.what());
  } catch (const std::bad_alloc&) {
    return fail(1, "out of memory (the scene, its textures or the image at this --res do not fit)");
  } catch (const std::exception& e) {
    return fail(1, e.what());
  }
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  const int status = run(argc, argv);
  lensrt::checkLeaksBeforeExit();
  return status;
}
