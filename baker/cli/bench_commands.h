// The benchmark command of the kiln command line (docs/bench.md).
#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace kiln::cli {

/// The folder `kiln bench` writes into when --out is not given: the full run's committed results
/// live in bench/ (README); the smoke run (--quick) and the catalogue report (--catalogue) go to
/// sub-folders of their own, so that neither overwrites them.
inline std::string DefaultBenchFolder(bool quick, bool catalogue) {
  if (catalogue) return "bench/catalogue";
  return quick ? "bench/quick" : "bench";
}

/// kiln bench [--quick] [--out DIR] [-j N]: bake time against bake and lookup error for kiln and
/// for Monte Carlo / Gauss-Legendre bakes of the same tables, thread scaling, the baker issue's
/// 128 x 128 ggx-dfg comparison and runtime ns per lookup; writes DIR/bench.csv and
/// DIR/bench.svg (DIR defaults to DefaultBenchFolder).
void RegisterBench(CLI::App& app);

}  // namespace kiln::cli
