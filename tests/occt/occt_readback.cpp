// occt_readback FILE.(step|stp|igs|iges) EXPECT.json: reads FILE with Open CASCADE, prints a
// JSON report (occt_check.hpp) on stdout, exits 0 only when the file passes every check.
#include <fstream>
#include <iostream>

#include "occt_check.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: occt_readback FILE.(step|stp|igs|iges) EXPECT.json\n";
    return 2;
  }
  pdesurf_occt::Expectation expect;
  try {
    std::ifstream in(argv[2]);
    if (!in) throw std::runtime_error(std::string("cannot open ") + argv[2]);
    expect = pdesurf_occt::parseExpectation(nlohmann::json::parse(in));
  } catch (const std::exception& e) {
    std::cerr << "occt_readback: " << e.what() << "\n";
    return 2;
  }
  const pdesurf_occt::CheckResult r = pdesurf_occt::checkCadFile(argv[1], expect);
  std::cout << r.report.dump(2) << "\n";
  return r.ok ? 0 : 1;
}
