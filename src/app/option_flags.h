// The option table's rows (api/option_table.h) as a command's CLI11
// options: each parses into the command's RenderSpec as it is read, with
// its row's check, so that a bad value is a usage error naming the flag.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "api/option_table.h"
#include "api/render_spec.h"

namespace lensrt {

class OptionFlags {
 public:
  // Adds every row `command` takes (kRenderCommand or kCompareCommand), or
  // those of `groups` alone (Option::group; a benchmark's camera flags);
  // `spec` must outlive the parse.
  OptionFlags(CLI::App& app, RenderSpec& spec, unsigned command, const std::vector<std::string>& groups = {});

  // The rows given on the command line (or by their environment variable).
  std::vector<const Option*> given() const;
  // Prints one warning for each given setting that does nothing here.
  void warnUnused(const RenderSpec& spec, bool quiet) const;

 private:
  unsigned command_;
  std::vector<std::pair<const Option*, CLI::Option*>> added_;
};

}  // namespace lensrt
