// --model on the CLI: the stated limits (limits --model) against the numeric evaluation of the
// programs the proofs name (evaluate --model), the multistart on a small model, and the refusals.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/common/run_cli.hpp"

namespace scalcal {
namespace {

using testing::run_cli;
using Json = nlohmann::json;

TEST(ModelCli, EvaluateOfTheSixPositionTestUnderAxis6ReachesItsLimits) {
  const auto e = run_cli("evaluate octahedral-2-0-0 --model axis6 --json");
  ASSERT_EQ(e.status, 0) << e.err;
  const Json j = Json::parse(e.out);
  EXPECT_EQ(j["model"], "axis6");
  EXPECT_EQ(j["parameters"].size(), 6u);
  EXPECT_EQ(j["rank"], 6);
  EXPECT_FALSE(j.contains("theta_nonorth"));  // axis6 has no non-orthogonality
  const auto l = run_cli("limits --model axis6 --json");
  ASSERT_EQ(l.status, 0) << l.err;
  const Json lim = Json::parse(l.out);
  for (const char* c : {"D", "A", "E", "S"})
    EXPECT_NEAR(j[c].get<double>() / lim[c]["value"].get<double>(), 1.0, 1e-12) << c;
  EXPECT_EQ(lim["D"]["exact"], "729");
}

TEST(ModelCli, Cubic12LimitsAgreeWithTheProgramsTheProofsName) {
  const auto l = run_cli("limits --model cubic12 --json");
  ASSERT_EQ(l.status, 0) << l.err;
  const Json lim = Json::parse(l.out);
  EXPECT_EQ(lim["model"], "cubic12");
  for (const char* key : {"exact", "value", "moments", "b", "measure", "attained", "proof"})
    EXPECT_TRUE(lim["D"].contains(key)) << key;
  EXPECT_EQ(lim["A"]["exact"], "99+9*sqrt(95)");
  // 10 positions per axis direction and 9 per cube diagonal: N = 132 (written as a program file).
  const auto d = run_cli("evaluate octahedral-10-0-9 --model cubic12 --json");
  ASSERT_EQ(d.status, 0) << d.err;
  EXPECT_NEAR(Json::parse(d.out)["D"].get<double>() / lim["D"]["value"].get<double>(), 1.0, 1e-11);
  const auto s = run_cli("evaluate octahedral-4-0-3 --model cubic12 --json");
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_NEAR(Json::parse(s.out)["S"].get<double>(), lim["S"]["value"].get<double>(), 1e-9);
  EXPECT_TRUE(Json::parse(s.out).contains("theta_cubic"));
}

TEST(ModelCli, OptimizeOnBias3ReachesItsLimitWithFivePositions) {
  const auto r = run_cli("optimize --model bias3 --positions 5 --criterion D --starts 2 --threads 1 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["model"], "bias3");
  EXPECT_NEAR(j["value"].get<double>(), 27.0, 1e-8);
  EXPECT_NEAR(j["efficiency"].get<double>(), 1.0, 1e-9);
}

TEST(ModelCli, RefusalsSayWhy) {
  const auto unknown = run_cli("evaluate classic18 --model paper10");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("--model"), std::string::npos) << unknown.err;
  const auto few = run_cli("optimize --model cubic12 --positions 10 --criterion D");
  EXPECT_EQ(few.status, 2);
  EXPECT_NE(few.err.find("12 parameters"), std::string::npos) << few.err;
  const auto region = run_cli("limits --model axis6 --region cap:30");
  EXPECT_EQ(region.status, 2);
  EXPECT_NE(region.err.find("paper9"), std::string::npos) << region.err;
  // Six distinct positions (each twice) cannot identify twelve parameters: the rank and the lost parameters are named.
  const auto rank = run_cli("evaluate octahedral-2-0-0 --model cubic12");
  EXPECT_EQ(rank.status, 2);
  EXPECT_NE(rank.err.find("rank 6 of 12"), std::string::npos) << rank.err;
  EXPECT_NE(rank.err.find("cubic_x"), std::string::npos) << rank.err;
}

TEST(ModelCli, FamilyAndEvaluateAgreeOnEveryModel) {
  // The same program, closed forms from the family's moments and the numeric evaluation.
  for (const char* m : {"axis6", "bias3", "cubic12"}) {
    const auto f = run_cli(
        std::string("family octahedral --param axes=2 --param edges=1 --param diagonals=1 --model ") + m + " --json");
    ASSERT_EQ(f.status, 0) << f.err;
    const auto e = run_cli(std::string("evaluate octahedral-2-1-1 --model ") + m + " --json");
    ASSERT_EQ(e.status, 0) << e.err;
    const Json fj = Json::parse(f.out), ej = Json::parse(e.out);
    EXPECT_EQ(fj["model"], m);
    for (const char* c : {"D", "A", "E", "S"})
      EXPECT_NEAR(fj[c].get<double>() / ej[c].get<double>(), 1.0, 1e-10) << m << c;
    EXPECT_EQ(fj.contains("theta_cubic"), std::string(m) == "cubic12") << m;
    EXPECT_EQ(fj.contains("theta_scale"), std::string(m) != "bias3") << m;
  }
  const auto p9 = run_cli("family octahedral --json");
  ASSERT_EQ(p9.status, 0) << p9.err;
  EXPECT_FALSE(Json::parse(p9.out).contains("model"));  // the paper's output keeps its keys
  EXPECT_FALSE(Json::parse(p9.out).contains("theta_cubic"));
  const auto singular = run_cli("family octahedral --param edges=0 --model cubic12");
  EXPECT_EQ(singular.status, 2);
  EXPECT_NE(singular.err.find("12 parameters of --model cubic12"), std::string::npos) << singular.err;
}

TEST(ModelCli, RandomSweepAndAugmentTakeTheModel) {
  const auto r = run_cli("random --model axis6 --positions 8 --count 2000 --threads 1 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const Json rj = Json::parse(r.out);
  EXPECT_EQ(rj["model"], "axis6");
  EXPECT_GE(rj["best"].get<double>(), 729.0 * (1 - 1e-12));
  const auto few = run_cli("random --model cubic12 --positions 11 --count 10");
  EXPECT_EQ(few.status, 2);
  EXPECT_NE(few.err.find("12 parameters"), std::string::npos) << few.err;

  // bias3 attains its D limit 27 at every N >= 3 (proofs/bias3_limits.md).
  const auto s = run_cli("sweep --model bias3 --positions 3..5 --criteria D --starts 2 --threads 1 --json --no-timing");
  ASSERT_EQ(s.status, 0) << s.err;
  const Json sj = Json::parse(s.out);
  ASSERT_EQ(sj.size(), 3u);
  for (const auto& row : sj) {
    EXPECT_EQ(row["model"], "bias3");
    EXPECT_EQ(row["limit"].get<double>(), 27.0);
    EXPECT_NEAR(row["ratio"].get<double>(), 1.0, 1e-9);
  }
  const auto low = run_cli("sweep --model axis6 --positions 5..7 --criteria D");
  EXPECT_EQ(low.status, 2);
  EXPECT_NE(low.err.find("6 parameters"), std::string::npos) << low.err;

  // Twice the six axis directions, then six more: three times the six-position test, which attains
  // axis6's A limit 18 (proofs/axis6_limits.md).
  const auto a = run_cli("augment --program octahedral-2-0-0 --add 6 --model axis6 --criterion A --json");
  ASSERT_EQ(a.status, 0) << a.err;
  const Json aj = Json::parse(a.out);
  EXPECT_EQ(aj["model"], "axis6");
  EXPECT_EQ(aj["added"].size(), 6u);
  EXPECT_NEAR(aj["value_before"].get<double>(), 18.0, 1e-9);
  EXPECT_NEAR(aj["value"].get<double>(), 18.0, 1e-6);
  // Judged against axis6's stated A limit on the sphere, as optimize and sweep judge it (was null).
  EXPECT_EQ(aj["limit"].get<double>(), 18.0);
  EXPECT_NEAR(aj["efficiency"].get<double>(), 1.0, 1e-6);
}

}  // namespace
}  // namespace scalcal
