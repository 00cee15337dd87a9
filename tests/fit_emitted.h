// Runs the C++ header `kiln fit` emits: compiled with the system compiler (-Werror) into a program
// that reads points on stdin and prints the channels, so a test compares the emitted code's floats
// with kiln's own evaluation and the exact integrals.
#pragma once
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_util.h"

namespace kiln::test {

/// Compiles several headers whose functions share the name `function` (forms of one table) in
/// one program, with -std=c++17 -O2 -Wall -Wextra -Werror, and runs it on `points`: each header's
/// body inside a namespace of its own (its own #includes, <algorithm> and <cmath>, come first at
/// global scope, so their guards keep them there), one program run per header. Returns the 4 output
/// slots per point of each header, in order.
inline std::vector<std::vector<float>> RunEmittedFits(const std::vector<std::string>& headers,
                                                      const std::string& function, int dims,
                                                      const std::vector<float>& points,
                                                      const std::string& dir) {
  std::ofstream main(dir + "/main.cpp");
  main << "#include <algorithm>\n#include <cmath>\n#include <cstdio>\n#include <cstdlib>\n";
  for (size_t k = 0; k < headers.size(); ++k) {
    std::ofstream(dir + "/fit" + std::to_string(k) + ".h") << headers[k];
    main << "namespace fit" << k << " {\n#include \"fit" << k << ".h\"\n}\n";
  }
  main << "int main(int argc, char** argv) {\n"
          "  const int k = argc > 1 ? std::atoi(argv[1]) : 0;\n"
          "  float x[4] = {0, 0, 0, 0}, out[4] = {0, 0, 0, 0};\n"
          "  for (;;) {\n    for (int i = 0; i < "
       << dims << "; ++i)\n      if (std::scanf(\"%a\", &x[i]) != 1) return 0;\n    switch (k) {\n";
  for (size_t k = 0; k < headers.size(); ++k)
    main << "      case " << k << ": fit" << k << "::" << function << "(x, out); break;\n";
  main << "    }\n    std::printf(\"%a %a %a %a\\n\", out[0], out[1], out[2], out[3]);\n  }\n}\n";
  main.close();
  const std::string cmd = "c++ -std=c++17 -O2 -Wall -Wextra -Werror -o " + dir + "/prog " + dir +
                          "/main.cpp > " + dir + "/cc.log 2>&1";
  const int status = std::system(cmd.c_str());
  INFO(ReadFile(dir + "/cc.log"));
  REQUIRE(status == 0);
  {
    std::ofstream in(dir + "/points.txt");
    for (float x : points) {
      char b[40];
      std::snprintf(b, sizeof b, "%a\n", x);
      in << b;
    }
  }
  std::vector<std::vector<float>> all;
  for (size_t k = 0; k < headers.size(); ++k) {
    const std::string run =
        dir + "/prog " + std::to_string(k) + " < " + dir + "/points.txt > " + dir + "/out.txt";
    REQUIRE(std::system(run.c_str()) == 0);
    std::istringstream out(ReadFile(dir + "/out.txt"));
    std::vector<float> values;
    for (size_t i = 0; i < 4 * (points.size() / dims); ++i) {
      std::string v;
      REQUIRE(static_cast<bool>(out >> v));
      values.push_back(std::strtof(v.c_str(), nullptr));
    }
    all.push_back(values);
  }
  return all;
}

/// Compiles `header`, whose function `function` takes `dims` axis values (at most 4), into `dir`
/// with -std=c++17 -O2 -Wall -Wextra -Werror, runs it on `points` (dims floats per point, in
/// order) and returns the 4 output slots per point (the channels first, zeros after them).
inline std::vector<float> RunEmittedFit(const std::string& header, const std::string& function,
                                        int dims, const std::vector<float>& points,
                                        const std::string& dir) {
  return RunEmittedFits({header}, function, dims, points, dir)[0];
}

}  // namespace kiln::test
