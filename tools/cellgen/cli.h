// What cellgen's modes share on the command line: usage errors and the frame of their main.
#pragma once

#include <algorithm>
#include <exception>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cellgen {

// A bad command line: exit status 2, the message followed by the usage.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline void require(bool ok, const std::string &message)
{
  if (!ok) throw UsageError(message);
}

// a number as in a message: 6 significant digits
inline std::string show(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

// The largest reference density (kg/m^3; water: 1000): far above any material's, it keeps the
// masses rho0 V finite.
constexpr double kRho0Max = 1e5;

// --help or -h anywhere prints the usage (status 0); else run(), whose errors are printed as
// "<name>: <message>", with the usage after a UsageError (status 2), alone otherwise (status 1).
template <class Run>
int runMain(int argc, char **argv, const char *name, const char *usage, Run run)
{
  const std::vector<std::string> words(argv + 1, argv + argc);
  if (std::find(words.begin(), words.end(), "--help") != words.end() ||
      std::find(words.begin(), words.end(), "-h") != words.end()) {
    std::cout << usage;
    return 0;
  }
  try {
    run();
  } catch (const UsageError &e) {
    std::cerr << name << ": " << e.what() << "\n" << usage;
    return 2;
  } catch (const std::exception &e) {
    std::cerr << name << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}    // namespace cellgen
