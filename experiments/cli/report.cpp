#include "experiments/cli/report.hpp"

#include <iostream>

namespace scalcal::cli {

int print_report(const Report& report, bool json) {
  if (json)
    print_json(report.json);
  else
    std::cout << report.text;
  return report.status;
}

}  // namespace scalcal::cli
