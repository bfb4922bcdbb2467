// `scalcal sweep` (sweep.hpp).
#include "commands/research/sweep.hpp"

#include <charconv>
#include <sstream>
#include <stdexcept>

#include "commands/core/region_request.hpp"
#include "commands/core/usage_error.hpp"
#include "commands/research/sweep_shards.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/region/region_limit.hpp"
#include "numeric/region/region_synthesis.hpp"

namespace scalcal::commands {
namespace {

bool read_int(const std::string& s, int& x) {
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
  return !s.empty() && ec == std::errc() && ptr == s.data() + s.size();
}

}  // namespace

std::optional<std::pair<int, int>> read_positions_range(const std::string& s) {
  const auto dots = s.find("..");
  int lo = 0, hi = 0;
  if (dots == std::string::npos ? !read_int(s, lo)
                                : !read_int(s.substr(0, dots), lo) || !read_int(s.substr(dots + 2), hi))
    return std::nullopt;
  if (dots == std::string::npos) hi = lo;
  if (lo < kSweepMinN || hi < lo || hi > kSweepMaxN) return std::nullopt;
  return std::make_pair(lo, hi);
}

std::vector<CriterionKind> read_criteria_list(const std::string& s) {
  std::vector<CriterionKind> out;
  std::stringstream list(s);
  for (std::string name; std::getline(list, name, ',');) {
    const auto c = parse_criterion(name);
    if (!c) return {};
    out.push_back(*c);
  }
  if (!s.empty() && s.back() == ',') return {};
  return out;
}

// A sweep spread over processes and time: the CLI keeps a shard's rows in a --results file for `merge`
// (a job array's tasks); Python's sweep(map=...) runs one shard per task through the caller's map.
Option shard_option() {
  Option o = text_option("--shard", "I/N",
                         words("run only the tasks k with k mod N = I (tasks: criteria outer, N inner), from 0/N to "
                               "N-1/N; the CLI needs {results} with it"));
  o.why_bad = [](const std::string& s) -> std::string {
    return read_shard(s) ? "" : "must be I/N with 0 <= I < N <= " + std::to_string(kMaxShards) + ", got '" + s + "'";
  };
  return o;
}

Option results_option() {
  Option o = text_option("--results", "FILE",
                         "keep each finished task as a line of FILE (its request on the first line); a run with "
                         "the same FILE resumes where the last one stopped; `scalcal merge` joins the shards' files",
                         "file path");
  o.cli_only = true;
  return o;
}

const CommandTable& sweep_table() {
  Option positions = text_option("--positions", "A..B", "N or a range A..B of N", "positions", "9..40");
  positions.why_bad = [](const std::string& s) -> std::string {
    return read_positions_range(s) ? ""
                                   : "must be N or A..B with " + std::to_string(kSweepMinN) +
                                         " <= A <= B <= " + std::to_string(kSweepMaxN) +
                                         " (and A at least the model's parameters), got '" + s + "'";
  };
  Option criteria = text_option("--criteria", "LIST", "comma-separated criteria", "none", criterion_names_text());
  criteria.fallback = scalcal::criterion_names(",");
  criteria.why_bad = [](const std::string& s) -> std::string {
    return read_criteria_list(s).empty()
               ? "must be a comma-separated list of " + criterion_names_text() + ", got '" + s + "'"
               : "";
  };
  static const CommandTable table{
      "sweep",
      "the best program for every N and criterion, and its ratio to the N -> infinity limit",
      42,
      {positions, criteria, model_option(), region_option(), starts_option(), seed_option(), threads_option(),
       out_option("also write the results as CSV, one row per N and criterion"),
       json_option("print a JSON array, one object per N and criterion, instead of the table"),
       flag_option("--no-timing", "leave out the seconds (output identical between runs)"), shard_option(),
       results_option()}};
  return table;
}

SweepRequest sweep_request(const Values& v) {
  SweepRequest q;
  std::tie(q.lo, q.hi) = *read_positions_range(v.text("--positions"));
  q.criteria = read_criteria_list(v.text("--criteria"));
  q.model = model_of(v);
  q.regions = v.list("--region");
  q.starts = static_cast<int>(v.integer("--starts"));
  q.seed = static_cast<std::uint64_t>(v.integer("--seed"));
  q.threads = static_cast<int>(v.integer("--threads"));
  return q;
}

Sweep::Sweep(const SweepRequest& q) : request_(q), limits_(kCriterionCount) {
  if (q.lo < model_parameters(q.model))
    throw UsageError(words("sweep: {positions} ") + std::to_string(q.lo) + " is below the " +
                     std::to_string(model_parameters(q.model)) + words(" parameters of {model} ") +
                     std::string(model_name(q.model)));
  const bool region_limits = model_supports(q.model, ModelCapability::region_limits);
  if (!region_limits && !is_sphere(q.regions)) throw region_limits_refusal("sweep", model_name(q.model));
  // --region sphere restricts nothing: a model without region limits sweeps the sphere with its stated limits.
  if (!q.regions.empty() && region_limits) region_ = resolve_region(q.regions, warnings_);
  for (const CriterionKind c : q.criteria)
    for (int n = q.lo; n <= q.hi; ++n) tasks_.push_back({c, n});
}

std::optional<double> Sweep::limit(CriterionKind c) const {
  auto& slot = limits_[static_cast<std::size_t>(c.index())];
  if (!slot) {
    std::optional<double> l;
    try {
      if (restricted())
        l = limit_value(c, *region_);
      else if (model_supports(request_.model, ModelCapability::criteria_native))
        l = criterion_limit(c).value;
      else if (const auto stated = stated_limit(request_.model, criterion_name(c)))
        l = stated->value;
    } catch (const std::invalid_argument&) {  // no known limit
    }
    slot = l;
  }
  return *slot;
}

SynthesisOptions Sweep::options(const SweepTask& t, int threads) const {
  SynthesisOptions opt;
  opt.positions = t.positions;
  opt.criterion = t.criterion;
  opt.starts = request_.starts;
  opt.seed = request_.seed;
  opt.threads = threads;
  opt.model = request_.model;
  return opt;
}

SynthesisResult Sweep::compute(const SweepTask& t, int threads, std::vector<LocalResult> known) const {
  SynthesisOptions opt = options(t, threads);
  if (restricted()) return synthesize_on_region(opt, *region_);
  opt.known_starts = std::move(known);
  return synthesize(opt);
}

int Sweep::certain_starts(const SweepTask& t) const {
  return restricted() ? 0 : scalcal::certain_starts(options(t, 1));
}

std::vector<LocalResult> Sweep::starts(const SweepTask& t, int first, int count, int threads) const {
  return multistart_starts(options(t, threads), first, count);
}

SweepRow Sweep::row(const SweepTask& t, SynthesisResult result) const {
  return {t, std::move(result), limit(t.criterion)};
}

Json to_json(const Sweep& sweep, const SweepRow& row, bool timing) {
  const SynthesisResult& r = row.result;
  const auto ratio = row.limit ? Json(r.value / *row.limit) : Json(nullptr);
  const auto limit = row.limit ? Json(*row.limit) : Json(nullptr);
  Json j{{"positions", row.task.positions},
         {"criterion", std::string(criterion_name(row.task.criterion))},
         {"value", r.value},
         {"ratio", ratio},
         {"program", program_json(r.program)},
         {"hits", r.hits},
         {"starts", r.starts},
         {"stopping", r.stopping},
         {"distinct", r.distinct}};
  if (timing) j["seconds"] = r.seconds;
  if (!is_default_model(sweep.request().model)) {
    j["model"] = std::string(model_name(sweep.request().model));
    j["limit"] = limit;
  }
  if (sweep.region()) {
    j["region"] = sweep.region()->text();
    j["limit"] = limit;
  }
  return j;
}

}  // namespace scalcal::commands
