#pragma once
/// \file
/// One case of the stability suite (report/stability.h): what it checks, its figure and its
/// limit. The suite's inputs (report/stability_inputs.h) and a basis's study (basis/study.h)
/// make cases.

#include <string>

namespace prt {

struct StabilityCase {
  std::string name;     ///< short identifier
  std::string checks;   ///< what is checked, one sentence
  double figure = 0;    ///< the measured number
  double limit = 0;     ///< pass if figure <= limit (or >= for `at_least`)
  bool at_least = false;
  bool pass = false;
  std::string note;     ///< extra measured context
};

}  // namespace prt
