// Uses kiln::runtime: loads the table named on the command line and prints every channel at the
// point given (physical coordinates, axis order), as `kiln sample FILE X Y` prints it.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "kiln/exr_loader.h"

int main(int argc, char** argv) {
  if (argc < 3) return std::puts("usage: sample_file TABLE.exr X [Y [Z]]"), 2;
  kiln::Table table;
  std::string error;
  if (!kiln::loadTable(argv[1], table, error)) return std::printf("%s\n", error.c_str()), 1;
  kiln::LutView lut = table.view();
  double x[3] = {0, 0, 0};
  for (int i = 2; i < argc && i < 5; ++i) x[i - 2] = std::strtod(argv[i], nullptr);
  float out[8] = {};
  lut.sample(x, out);
  for (int c = 0; c < lut.channels && c < 8; ++c)
    std::printf(c ? " %.17g" : "%.17g", double(out[c]));
  std::printf("\n");
  return 0;
}
