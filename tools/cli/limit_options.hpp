#pragma once
// The options that lift the limits decided at validation (tools/io/resource_limits.hpp,
// cases/README.md "Limits"): --max-memory-gb G and --allow-large, on every command that
// estimates its work (run, wave, regress).
#include <CLI/CLI.hpp>

#include "tools/io/resource_limits.hpp"

namespace stoneskip::cli {

void add_limit_options(CLI::App* cmd, ResourceLimits& limits);

}  // namespace stoneskip::cli
