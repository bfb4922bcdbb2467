// `scalcal certify` as a function: proves that a program attains a limit (an exact program within a
// radius) or is a strict local optimum (its value enclosed), by interval arithmetic (numeric/certify).
#pragma once
#include <string>

#include "commands/core/common_options.hpp"
#include "commands/core/json.hpp"
#include "commands/core/progress.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/certify/certify.hpp"

namespace scalcal::commands {

struct CertifyRequest {
  std::string name;  // the program's name in messages
  Program program;
  CriterionKind criterion = CriterionKind::D;
  int digits = 60;
};

struct CertifyCommandResult {
  CriterionKind criterion = CriterionKind::D;
  int positions = 0;
  CertifyResult certificate;
  Warnings warnings;
  bool local() const { return !certificate.enclosure_lo.empty(); }  // a certified local optimum
};

// PROGRAM --criterion C [--digits P] [--json]
const CommandTable& certify_table();
CertifyRequest certify_request(const Values& values);

// Throws UsageError for fewer than 9 positions, a singular program or a criterion without a known
// limit ("no known limit for criterion X").
CertifyCommandResult certify(const CertifyRequest& request, const Progress& progress = {});

Json to_json(const CertifyCommandResult& result);

}  // namespace scalcal::commands
