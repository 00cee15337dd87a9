// kiln bench --custom-lobe FILE.cpp: the bake time of a user's lobe's 128 x 128 albedo table
// against a built-in model's, both by adaptive quadrature to the same tolerance (the built-in's
// fixed rule set aside), in interleaved rounds of one run: medians of wall and CPU time, their
// ratios, and the largest difference of the two bakes' node values.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

namespace kiln {

struct CustomLobeBenchOptions {
  std::string source;           ///< the lobe: a C++ source (.cpp) or a shared library (.so)
  std::string against = "ggx";  ///< the built-in model whose albedo is timed alongside
  int size = 128;               ///< nodes per axis of both albedo tables
  int rounds = 5;               ///< timed bakes of each table, interleaved (lobe, built-in, ...)
  int threads = 2;              ///< threads of each bake
};

struct CustomLobeBenchResult {
  std::string lobeTable, builtinTable;              ///< "<id>-albedo", "<against>-albedo"
  double tol = 0;                                   ///< the tolerance both bakes integrate to
  std::vector<double> lobeSeconds, builtinSeconds;  ///< wall time of each round
  std::vector<double> lobeCpu, builtinCpu;          ///< CPU seconds of each round (all threads)
  double lobeMedian = 0, builtinMedian = 0, lobeCpuMedian = 0, builtinCpuMedian = 0;
  double ratio = 0;     ///< lobeMedian / builtinMedian (wall)
  double cpuRatio = 0;  ///< the same for the CPU seconds, steadier on a shared machine
  long long lobeEvals = 0, builtinEvals = 0;  ///< integrand evaluations of one bake
  double maxDifference = 0;                   ///< max |lobe - built-in| over the nodes
};

/// Loads the lobe (LoadModelSource for a .cpp, else LoadModelLibrary), then bakes the node
/// values of both albedo tables (each spec's own axes at opt.size nodes, the lobe's tolerance
/// for both; every node as the bake evaluates it, NodeEvaluationPoint) by adaptive quadrature on
/// opt.threads threads, alternating lobe and built-in for opt.rounds rounds after one untimed
/// warm-up of each. Prints one line per round and the summary to `log` when it is not null.
/// Throws std::invalid_argument for a lobe that does not load or has no albedo table, or an
/// unknown built-in model.
CustomLobeBenchResult RunCustomLobeBench(const CustomLobeBenchOptions& opt, std::FILE* log);

}  // namespace kiln
