// make stability: the matrix of stiff and extreme cases (report/STABILITY.md).
#include <chrono>
#include <fstream>
#include <iostream>

#include "numerics/stability.hpp"

using namespace physics::numerics;

int main(int argc, char** argv) {
  const std::string out_path = argc > 1 ? argv[1] : "report/STABILITY.md";
  const bool quick = argc > 2 && std::string(argv[2]) == "--quick";  // skip the long cases
  const auto modes = stability_modes();
  const auto cases = stability_cases();
  std::ofstream md(out_path);
  if (!md) {
    std::cerr << "stability: cannot write " << out_path << "\n";
    return 2;
  }
  md << "| case | criterion |";
  for (const Mode& m : modes) md << " " << m.name << " |";
  md << "\n|---|---|";
  for (std::size_t i = 0; i < modes.size(); ++i) md << "---|";
  md << "\n";
  int fails = 0, unexpected = 0;
  for (const StabilityCase& c : cases) {
    if (quick && c.slow) continue;
    md << "| " << c.name << " | " << c.criterion << " |";
    for (const Mode& m : modes) {
      const auto t0 = std::chrono::steady_clock::now();
      const Outcome o = c.run(m);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      md << " " << (o.pass ? "pass" : "**FAIL**") << ": " << o.figure << " |";
      fails += o.pass ? 0 : 1;
      const bool surprise = o.pass == expected_to_fail(c.name, m.name);
      unexpected += surprise ? 1 : 0;
      std::cout << (o.pass ? "pass " : "FAIL ") << c.name << " [" << m.name << "]: " << o.figure << " (" << s << " s)"
                << (surprise ? "  <-- not as expected" : "") << std::endl;
    }
    md << "\n";
  }
  std::cout << fails << " failing cells, " << unexpected << " not as expected; wrote " << out_path << "\n";
  return 0;
}
