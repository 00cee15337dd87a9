// The benchmark command of the kiln command line (docs/bench.md).
#pragma once
#include <CLI/CLI.hpp>

namespace kiln::cli {

/// kiln bench [--quick] [--out DIR] [-j N]: bake time against bake and lookup error for kiln and
/// for Monte Carlo / Gauss-Legendre bakes of the same tables, thread scaling, the baker issue's
/// 128 x 128 ggx-dfg comparison and runtime ns per lookup; writes DIR/bench.csv and
/// DIR/bench.svg (DIR defaults to bench/).
void RegisterBench(CLI::App& app);

}  // namespace kiln::cli
