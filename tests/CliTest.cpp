// SPDX-License-Identifier: BSD-3-Clause
// shadinglab brdf: CSV format, values, and error exits.
#include "CliTestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

using shadinglab::testing::CountLines;
using shadinglab::testing::RunCli;

namespace
{
std::vector<std::vector<double>> ParseCsv(const std::string& text, std::string& header)
{
  std::stringstream ss(text);
  std::getline(ss, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(ss, line))
  {
    std::vector<double> row;
    std::stringstream ls(line);
    std::string cell;
    while (std::getline(ls, cell, ','))
    {
      row.push_back(std::stod(cell));
    }
    rows.push_back(row);
  }
  return rows;
}
} // namespace

TEST(CliTest, BrdfFresnelTableHasHeaderRowsAndKnownValues)
{
  const auto r = RunCli("brdf --model cook-torrance --m 0.3 --eta 1.5 --theta-l 0:90:5 "
                        "--theta-v 30 --phi 180 --term F");
  ASSERT_EQ(r.status, 0) << r.err;
  std::string header;
  const auto rows = ParseCsv(r.out, header);
  EXPECT_EQ(header, "theta_l,theta_v,phi,r,g,b");
  ASSERT_EQ(rows.size(), 19u);
  for (const auto& row : rows)
  {
    ASSERT_EQ(row.size(), 6u);
  }
  // theta_l = 30 = theta_v, mirror side: H = N, L.H = cos 30.
  // theta_l = 90, theta_v = 30: L.H = cos 60 -> F = 0.08919 (REFERENCE.md).
  EXPECT_NEAR(rows.back()[3], 0.08919, 5e-6);
  EXPECT_EQ(rows.back()[0], 90.0);
}

TEST(CliTest, BrdfPrintsAtLeastNineSignificantDigits)
{
  const auto r = RunCli("brdf --theta-l 0 --theta-v 0 --term F --eta 1.7");
  ASSERT_EQ(r.status, 0) << r.err;
  // F0 = (0.7/2.7)^2 = 0.0672153635116598...
  EXPECT_NE(r.out.find("0.06721536351"), std::string::npos) << r.out;
}

TEST(CliTest, BrdfDAndGTermsAndMixture)
{
  // Normal incidence and view: alpha = 0, D = 1/m^2 (mixture: sum w/m^2).
  auto r = RunCli("brdf --theta-l 0 --theta-v 0 --term D --m 0.2,0.5 --w 0.25,0.75");
  ASSERT_EQ(r.status, 0) << r.err;
  std::string header;
  auto rows = ParseCsv(r.out, header);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_NEAR(rows[0][3], 0.25 / 0.04 + 0.75 / 0.25, 1e-9);
  r = RunCli("brdf --theta-l 0 --theta-v 0 --term G");
  ASSERT_EQ(r.status, 0) << r.err;
  rows = ParseCsv(r.out, header);
  EXPECT_EQ(rows[0][3], 1.0);
}

TEST(CliTest, BrdfPerChannelEtaAndConductor)
{
  const auto r = RunCli("brdf --theta-l 0 --theta-v 0 --term F --eta 1.5,1.0,0.35 --k 0,0,2.714");
  ASSERT_EQ(r.status, 0) << r.err;
  std::string header;
  const auto rows = ParseCsv(r.out, header);
  EXPECT_NEAR(rows[0][3], 0.04, 1e-12);
  EXPECT_EQ(rows[0][4], 0.0);
  EXPECT_NEAR(rows[0][5], 0.8476, 5e-5);
}

TEST(CliTest, BrdfLambertIsAlbedoOverPi)
{
  const auto r = RunCli("brdf --model lambert --theta-l 0:80:20 --theta-v 10,50 --phi 0,90");
  ASSERT_EQ(r.status, 0) << r.err;
  std::string header;
  const auto rows = ParseCsv(r.out, header);
  ASSERT_EQ(rows.size(), 5u * 2u * 2u);
  for (const auto& row : rows)
  {
    EXPECT_NEAR(row[3], 1.0 / 3.14159265358979, 1e-9);
  }
}

TEST(CliTest, BrdfVariantsDifferByFour)
{
  const auto a = RunCli("brdf --theta-l 40 --theta-v 40 --variant 1982");
  const auto b = RunCli("brdf --theta-l 40 --theta-v 40 --variant walter");
  ASSERT_EQ(a.status, 0);
  ASSERT_EQ(b.status, 0);
  std::string h;
  EXPECT_NEAR(ParseCsv(a.out, h)[0][3], 4.0 * ParseCsv(b.out, h)[0][3], 1e-8);
}

TEST(CliTest, BadArgumentsExitTwoWithOneLineError)
{
  const char* bad[] = {
    "brdf",                                       // missing --theta-l
    "brdf --theta-l 0:90:0",                      // zero step
    "brdf --theta-l 0:90:-5",                     // negative step
    "brdf --theta-l abc",                         // not a number
    "brdf --theta-l 95",                          // out of range
    "brdf --theta-l nan",                         // not finite
    "brdf --theta-l 10 --kd 0.8 --ks 0.5",        // kd + ks > 1
    "brdf --theta-l 10 --m 0",                    // m = 0
    "brdf --theta-l 10 --m 0.2,0.4 --w 0.2,0.2", // weights do not sum to 1
    "brdf --theta-l 10 --eta -1",                 // eta < 0
    "brdf --theta-l 10 --eta 1,2",                // two channels
    "brdf --theta-l 10 --term X",                 // unknown term
    "brdf --theta-l 10 --model lambert --term F", // term needs cook-torrance
    "brdf --theta-l 10 --bogus 1",                // unknown option
    "brdf --theta-l 0:90:0.000001 --theta-v 0:90:0.001", // absurd row count
    "frobnicate",                                 // unknown command
  };
  for (const char* args : bad)
  {
    const auto r = RunCli(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(CountLines(r.err), 1) << args << ": " << r.err.substr(0, 300);
    EXPECT_NE(r.err.find("error"), std::string::npos) << args;
  }
}
