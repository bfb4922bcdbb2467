// Shards, result files and their merge (sweep_shards.hpp).
#include "commands/research/sweep_shards.hpp"

#include <charconv>
#include <istream>
#include <stdexcept>

#include "commands/core/common_options.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {
namespace {

// The result file's mark on its first line, with the format's version.
constexpr const char* kFormat = "scalcal sweep results";
constexpr int kFormatVersion = 1;

Json request_json(const SweepRequest& q) {
  Json criteria = Json::array();
  for (const CriterionKind c : q.criteria) criteria.push_back(std::string(criterion_name(c)));
  return Json{{"format", kFormat},
              {"version", kFormatVersion},
              {"positions", {q.lo, q.hi}},
              {"criteria", criteria},
              {"model", std::string(model_name(q.model))},
              {"regions", q.regions},
              {"starts", q.starts},
              {"seed", q.seed}};
}

// The request a header names; nullopt when it is not a sweep's header of this format.
std::optional<SweepRequest> request_of(const Json& j) {
  if (!j.is_object() || j.value("format", std::string()) != kFormat || j.value("version", 0) != kFormatVersion)
    return std::nullopt;
  SweepRequest q;
  q.lo = j.at("positions").at(0).get<int>();
  q.hi = j.at("positions").at(1).get<int>();
  q.criteria.clear();
  for (const auto& name : j.at("criteria")) {
    const auto c = parse_criterion(name.get<std::string>());
    if (!c) return std::nullopt;
    q.criteria.push_back(*c);
  }
  const auto model = parse_model(j.at("model").get<std::string>());
  if (!model) return std::nullopt;
  q.model = *model;
  q.regions = j.at("regions").get<std::vector<std::string>>();
  q.starts = j.at("starts").get<int>();
  q.seed = j.at("seed").get<std::uint64_t>();
  return q;
}

SynthesisResult result_of(const Json& j) {
  SynthesisResult r;
  r.value = j.at("value").get<double>();
  r.starts = j.at("starts").get<int>();
  r.stopping = j.at("stopping").get<std::string>();
  r.hits = j.at("hits").get<int>();
  r.distinct = j.at("distinct").get<int>();
  r.local_solver = j.at("local_solver").get<std::string>();
  r.seconds = j.at("seconds").get<double>();
  for (const auto& p : j.at("program"))
    r.program.positions.emplace_back(p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>());
  return r;
}

// Equal as the output shows them (seconds aside: they are the run's, not the result's).
bool same_result(const SynthesisResult& a, const SynthesisResult& b) {
  return a.value == b.value && a.starts == b.starts && a.stopping == b.stopping && a.hits == b.hits &&
         a.distinct == b.distinct && a.program.positions == b.program.positions;
}

std::string task_name(const Sweep& sweep, std::size_t k) {
  const SweepTask& t = sweep.tasks()[k];
  return std::string(criterion_name(t.criterion)) + " N = " + std::to_string(t.positions);
}

}  // namespace

std::optional<Shard> read_shard(const std::string& s) {
  const auto slash = s.find('/');
  if (slash == std::string::npos) return std::nullopt;
  Shard out;
  const auto whole = [](const std::string& t, int& x) {
    const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
    return !t.empty() && ec == std::errc() && p == t.data() + t.size();
  };
  if (!whole(s.substr(0, slash), out.index) || !whole(s.substr(slash + 1), out.count)) return std::nullopt;
  if (out.count < 1 || out.count > kMaxShards || out.index < 0 || out.index >= out.count) return std::nullopt;
  return out;
}

std::vector<std::size_t> shard_tasks(const Sweep& sweep, const Shard& shard) {
  std::vector<std::size_t> out;
  for (std::size_t k = static_cast<std::size_t>(shard.index); k < sweep.tasks().size();
       k += static_cast<std::size_t>(shard.count))
    out.push_back(k);
  return out;
}

std::string results_header(const SweepRequest& request) { return json_text(request_json(request)); }

namespace {

Json task_json(const Sweep& sweep, std::size_t k) {
  const SweepTask& t = sweep.tasks()[k];
  return Json{{"task", k}, {"criterion", std::string(criterion_name(t.criterion))}, {"positions", t.positions}};
}

}  // namespace

std::string result_line(const Sweep& sweep, std::size_t k, const SynthesisResult& r) {
  Json j = task_json(sweep, k);
  j.update(Json{{"value", r.value},
                {"starts", r.starts},
                {"stopping", r.stopping},
                {"hits", r.hits},
                {"distinct", r.distinct},
                {"local_solver", r.local_solver},
                {"seconds", r.seconds},
                {"program", program_json(r.program)}});
  return json_text(j);
}

std::string error_line(const Sweep& sweep, std::size_t k, const std::string& what) {
  Json j = task_json(sweep, k);
  j["error"] = what;
  return json_text(j);
}

TaskLine read_task_line(const Sweep& sweep, const std::string& line) {
  Json j;
  try {
    j = Json::parse(line);
  } catch (const std::exception&) {
    throw std::invalid_argument("not a line of a sweep's result file (JSON)");
  }
  TaskLine out;
  out.task = j.is_object() ? j.value("task", sweep.tasks().size()) : sweep.tasks().size();
  if (out.task >= sweep.tasks().size() ||
      j.value("criterion", std::string()) != criterion_name(sweep.tasks()[out.task].criterion) ||
      j.value("positions", 0) != sweep.tasks()[out.task].positions)
    throw std::invalid_argument("a task the sweep on its first line does not have");
  if (j.contains("error")) {
    out.error = j.at("error").get<std::string>();
    return out;
  }
  try {
    out.result = result_of(j);
  } catch (const std::exception&) {
    throw std::invalid_argument("a task's line without all of its result");
  }
  return out;
}

ResultFile read_result_file(std::istream& in, const std::string& file) {
  ResultFile out;
  out.file = file;
  std::string line;
  int number = 0;
  std::optional<Sweep> sweep;
  while (std::getline(in, line)) {
    ++number;
    if (in.eof()) {  // no newline: a line cut off by a killed run
      out.partial_line = !line.empty();
      break;
    }
    if (number == 1) {
      std::optional<SweepRequest> q;
      try {
        q = request_of(Json::parse(line));
      } catch (const std::exception&) {  // not JSON, or a field of the wrong kind: not a header
      }
      if (!q) throw InputError(file, 1, "not a sweep's result file (its first line names no sweep request)");
      out.request = *q;
      sweep.emplace(out.request);
    } else {
      TaskLine t;
      try {
        t = read_task_line(*sweep, line);
      } catch (const std::invalid_argument& e) {
        throw InputError(file, number, e.what());
      }
      if (!t.result) throw InputError(file, number, "a failed task (" + t.error + ")");
      const std::size_t k = t.task;
      if (const auto seen = out.results.find(k); seen != out.results.end() && !same_result(seen->second, *t.result))
        throw InputError(file, number, task_name(*sweep, k) + " is recorded twice with different results");
      out.results[k] = *t.result;
    }
    out.whole_bytes += line.size() + 1;
  }
  if (number == 0 || !sweep)
    throw InputError(file, 0, "empty: not a sweep's result file (its first line names the sweep request)");
  return out;
}

std::string request_difference(const SweepRequest& a, const SweepRequest& b) {
  const auto criteria = [](const SweepRequest& q) {
    std::string s;
    for (const CriterionKind c : q.criteria) s += (s.empty() ? "" : ",") + std::string(criterion_name(c));
    return s;
  };
  const auto regions = [](const SweepRequest& q) {
    std::string s;
    for (const auto& r : q.regions) s += (s.empty() ? "" : " ") + r;
    return s.empty() ? std::string("sphere") : s;
  };
  if (a.lo != b.lo || a.hi != b.hi)
    return words("{positions} ") + std::to_string(a.lo) + ".." + std::to_string(a.hi) + " against " +
           std::to_string(b.lo) + ".." + std::to_string(b.hi);
  if (criteria(a) != criteria(b)) return words("{criteria} ") + criteria(a) + " against " + criteria(b);
  if (a.model != b.model)
    return words("{model} ") + std::string(model_name(a.model)) + " against " + std::string(model_name(b.model));
  if (a.regions != b.regions) return words("{region} ") + regions(a) + " against " + regions(b);
  if (a.starts != b.starts)
    return words("{starts} ") + std::to_string(a.starts) + " against " + std::to_string(b.starts);
  if (a.seed != b.seed) return words("{seed} ") + std::to_string(a.seed) + " against " + std::to_string(b.seed);
  return "";
}

std::vector<SynthesisResult> merge_results(const std::vector<ResultFile>& files, const Sweep& sweep) {
  std::vector<std::optional<SynthesisResult>> found(sweep.tasks().size());
  std::vector<std::string> from(sweep.tasks().size());
  for (const ResultFile& f : files) {
    if (const std::string d = request_difference(sweep.request(), f.request); !d.empty())
      throw InputError(f.file, 1, "a result file of another sweep (" + d + " in " + files.front().file + ")");
    for (const auto& [k, r] : f.results) {
      if (found[k] && !same_result(*found[k], r))
        throw InputError(f.file, 0, task_name(sweep, k) + " differs from its result in " + from[k]);
      found[k] = r;
      from[k] = f.file;
    }
  }
  std::vector<std::string> missing;
  for (std::size_t k = 0; k < found.size(); ++k)
    if (!found[k]) missing.push_back(task_name(sweep, k) + " (task " + std::to_string(k) + ")");
  if (!missing.empty()) {
    std::string list;
    for (std::size_t i = 0; i < missing.size() && i < 10; ++i) list += (i ? ", " : "") + missing[i];
    if (missing.size() > 10) list += ", ...";
    throw InputError(files.front().file, 0,
                     std::to_string(missing.size()) + " of the sweep's " + std::to_string(found.size()) +
                         " tasks are in no result file: " + list +
                         words(" (run the shards that hold them again with the same {results} file: they resume)"));
  }
  std::vector<SynthesisResult> out;
  out.reserve(found.size());
  for (auto& r : found) out.push_back(std::move(*r));
  return out;
}

const CommandTable& merge_table() {
  Option results = text_option(
      "--results", "FILE", words("a result file of `sweep {results}`, or a folder of them (*.jsonl); repeat for more"),
      "file path", kRequired);
  results.kind = OptionKind::repeated;
  static const CommandTable table{
      "merge",
      "join the result files of a sweep's shards and print the sweep as one process would",
      43,
      {results, out_option("also write the results as CSV, one row per N and criterion"),
       json_option("print a JSON array, one object per N and criterion, instead of the table"),
       flag_option("--no-timing", "leave out the seconds (output identical between runs)")}};
  return table;
}

}  // namespace scalcal::commands
