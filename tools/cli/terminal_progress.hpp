#pragma once
// Progress bars on stderr (tools/io/progress.hpp: an updating line on a terminal, a line per 10 %
// otherwise) for the tickers the studies ask for (verification/study/progress.hpp).
#include "verification/study/progress.hpp"

namespace stoneskip::cli {

ProgressFactory terminal_progress();

}  // namespace stoneskip::cli
