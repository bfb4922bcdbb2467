// --instrument gyro on the design commands and simulate: the rate table's reach is the union the
// user could write by hand (cap:DEG and cap:DEG:0,0,-1), and a gyro's rehearsal is a log calibrate
// reads, with its truth.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "commands/core/usage_error.hpp"
#include "commands/design/gyro_regions.hpp"
#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

using Json = nlohmann::json;

TEST(GyroCli, DesignOnARateTableIsOnTheRegionAndItsAntipode) {
  // optimize judges its program against the region's D limit: the same with --instrument gyro as
  // with the union written by hand.
  const CliResult gyro =
      run_cli("optimize --positions 12 --criterion D --starts 1 --region cap:40 --instrument gyro --json");
  const CliResult by_hand =
      run_cli("optimize --positions 12 --criterion D --starts 1 --region cap:40 --region cap:40:0,0,-1 --json");
  ASSERT_EQ(gyro.status, 0) << gyro.err;
  ASSERT_EQ(by_hand.status, 0) << by_hand.err;
  const Json a = Json::parse(gyro.out), b = Json::parse(by_hand.out);
  EXPECT_EQ(a["region"], "cap:40 + cap:40:0,0,-1");
  EXPECT_EQ(a["region"], b["region"]);
  EXPECT_EQ(a["limit"], b["limit"]);
  const CliResult refused = run_cli("limits --instrument gyro --region candidates:none.csv");
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("list both directions"), std::string::npos) << refused.err;
}

// jig --instrument gyro: the program the table measures is the faces' normals and their antipodes; evaluate
// of that doubled program, written by hand from the jig's own, gives the value jig reports.
TEST(GyroCli, AJigOnARateTableMeasuresItsFacesBothWays) {
  const std::string faces = (scratch_dir() / "jig_faces.csv").string(),
                    both = (scratch_dir() / "jig_both.csv").string();
  const CliResult j = run_cli("jig rhombic-dodecahedron --criterion A --instrument gyro --json --out " + faces);
  ASSERT_EQ(j.status, 0) << j.err;
  const Json r = Json::parse(j.out);
  EXPECT_EQ(r["instrument"], "gyro");
  EXPECT_NE(r["instrument_note"].get<std::string>().find("opposite pairs"), std::string::npos);
  std::istringstream in(slurp(faces));
  std::ofstream out(both);
  std::string line;
  std::getline(in, line);
  out << "x,y,z\n";
  while (std::getline(in, line)) {
    double x, y, z;
    char c;
    std::istringstream f(line);
    f >> x >> c >> y >> c >> z;
    out.precision(17);
    out << x << ',' << y << ',' << z << '\n' << -x << ',' << -y << ',' << -z << '\n';
  }
  out.close();
  const CliResult e = run_cli("evaluate " + both + " --json");
  ASSERT_EQ(e.status, 0) << e.err;
  const Json ev = Json::parse(e.out);
  EXPECT_NEAR(ev["A"].get<double>(), r["value"].get<double>(), 1e-9 * r["value"].get<double>()) << e.out;
  // The accelerometer's answer, the same.
  const Json accel = Json::parse(run_cli("jig rhombic-dodecahedron --criterion A --json").out);
  EXPECT_EQ(accel["value"], r["value"]);
}

TEST(GyroCli, ReversedSpecs) {
  using commands::with_reversed_turns;
  EXPECT_EQ(with_reversed_turns({"cap:30"}), (std::vector<std::string>{"cap:30", "cap:30:0,0,-1"}));
  EXPECT_EQ(with_reversed_turns({"band:10:20:1,0,0"}),
            (std::vector<std::string>{"band:10:20:1,0,0", "band:10:20:-1,0,0"}));
  EXPECT_EQ(with_reversed_turns({"faces:10", "sphere"}), (std::vector<std::string>{"faces:10", "sphere"}));
  EXPECT_THROW(with_reversed_turns({"candidates:x.csv"}), UsageError);
}

TEST(GyroCli, RehearsalsWriteLogsAndTruth) {
  const std::string log = (scratch_dir() / "gyro_rt.csv").string(), truth = (scratch_dir() / "gyro_rt.json").string();
  const CliResult r = run_cli("simulate --instrument gyro --program dodecahedral-12 --noise 1e-3 --dwell 4 --log " +
                              log + " --truth " + truth);
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream text(slurp(log));
  std::string header;
  std::getline(text, header);
  EXPECT_EQ(header, "t,ix,iy,iz,rate");
  const Json t = Json::parse(slurp(truth));
  EXPECT_EQ(t["instrument"], "gyro");
  EXPECT_EQ(t["method"], "rate_table");
  const std::string acc = (scratch_dir() / "gyro_acc.csv").string();
  const CliResult h = run_cli("simulate --instrument gyro --program octahedral-1-1-1 --noise 1e-3 --dwell 2 --log " +
                              log + " --accelerometer " + acc + " --json");
  ASSERT_EQ(h.status, 0) << h.err;
  EXPECT_EQ(Json::parse(h.out)["method"], "hand_rotations");
  EXPECT_EQ(run_cli("simulate --instrument gyro --program dodecahedral-12 --noise 1e-3 --bench-file " + log).status, 2);
  EXPECT_EQ(run_cli("simulate --program dodecahedral-12 --noise 1e-3 --log " + log + " --turn-angle 360").status, 2);
}

}  // namespace
}  // namespace scalcal::testing
