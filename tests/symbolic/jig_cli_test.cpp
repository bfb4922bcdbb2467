// `scalcal jig` and the jig programs through the real binary: documented JSON keys, values against
// hand-derived ones, and exit 2 on bad names, parameters and rank-deficient jigs.
#include <gtest/gtest.h>

#include <string>

#include "tests/common/run_cli.hpp"

namespace {

using scalcal::testing::run_cli;

TEST(JigCli, JsonKeysAndTheCuboctahedronsA) {
  const auto r = run_cli("jig cuboctahedron --criterion A --starts 8 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* key : {"\"jig\": \"jig:cuboctahedron\"", "\"criterion\": \"A\"", "\"orientation\": [",
                          "\"value\": ", "\"value_default_orientation\": 73.25", "\"program\": [",
                          "\"limit_claim\": \"never reached\"", "\"limit_claim_proven\": true"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key << "\n" << r.out;
}

TEST(JigCli, ProvenCases) {
  // The rhombic dodecahedron's 12 faces are the 12 edge positions: E = 12, the limit (by hand: b = 1/12).
  const auto rd = run_cli("jig rhombic-dodecahedron --criterion E --starts 4 --json");
  ASSERT_EQ(rd.status, 0) << rd.err;
  EXPECT_NE(rd.out.find("\"limit_claim\": \"reached at the default mounting\""), std::string::npos) << rd.out;
  // An icosahedral jig: the same in every mounting, D at the limit 61509375/4.
  const auto ico = run_cli("jig jig:icosidodecahedron --criterion D --json");
  ASSERT_EQ(ico.status, 0) << ico.err;
  EXPECT_NE(ico.out.find("\"value\": 15377343.75"), std::string::npos) << ico.out;
  EXPECT_NE(ico.out.find("\"limit_claim\": \"reached in every orientation\""), std::string::npos) << ico.out;
  EXPECT_NE(ico.out.find("\"value_status\": \"proven\""), std::string::npos) << ico.out;
}

TEST(JigCli, EveryJigIsAProgramEverywhere) {
  EXPECT_EQ(run_cli("evaluate jig:truncated-icosahedron --json").status, 0);
  const auto cat = run_cli("catalogue");
  ASSERT_EQ(cat.status, 0);
  for (const char* name : {"jig:cube", "jig:rhombic-triacontahedron", "jig:truncated-cube"})
    EXPECT_NE(cat.out.find(name), std::string::npos) << name;
  const auto opt = run_cli("optimize --from jig:cuboctahedron --criterion D --starts 1 --threads 1 --json");
  ASSERT_EQ(opt.status, 0) << opt.err;
  EXPECT_NE(opt.out.find("\"positions\": 14"), std::string::npos) << opt.out;
  EXPECT_EQ(run_cli("family jig:cuboctahedron --param orientation=aa:0,0,1,t --json").status, 0);
}

TEST(JigCli, BadInputExits2) {
  for (const char* bad :
       {"jig tetrahedron", "jig cube", "jig octahedron --criterion A", "jig cuboctahedron --criterion Q",
        "jig cuboctahedron --starts 0", "evaluate jig:cube@orientation=aa:0,0,0,1",
        "evaluate jig:cube@orientation=rows:1,0,0,0,1,0,0,0,-1", "family jig:cube --param orientation=x",
        "optimize --from jig:cuboctahedron --positions 15 --criterion D",
        "optimize --from jig:cuboctahedron --region cap:60 --criterion D"}) {
    const auto r = run_cli(bad);
    EXPECT_EQ(r.status, 2) << bad << "\n" << r.err;
    EXPECT_FALSE(r.err.empty()) << bad;
  }
  const auto cube = run_cli("jig cube");
  EXPECT_NE(cube.err.find("not identifiable: nonorth_xy, nonorth_yz, nonorth_zx"), std::string::npos) << cube.err;
}

}  // namespace
