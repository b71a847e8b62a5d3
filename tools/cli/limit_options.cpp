#include "tools/cli/limit_options.hpp"

#include <cmath>
#include <cstdlib>
#include <string>

namespace stoneskip::cli {

void add_limit_options(CLI::App* cmd, ResourceLimits& limits) {
  cmd->add_option_function<double>(
         "--max-memory-gb", [&limits](double gb) { limits.max_memory_bytes = gb * 1e9; },
         "Refuse a run estimated to need more memory than this (GB; default 8)")
      ->check(CLI::Range(0.001, 1e6))
      // CLI::Range lets NaN through (every comparison with it is false): refused by name.
      ->check([](const std::string& s) {
        return std::isnan(std::strtod(s.c_str(), nullptr)) ? "not a number: " + s : std::string();
      });
  cmd->add_flag("--allow-large", limits.allow_large,
                "Run even when the estimated work (steps, cell updates) exceeds the documented limits");
}

}  // namespace stoneskip::cli
