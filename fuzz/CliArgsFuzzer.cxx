// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the CLI's argument parser on arbitrary argument lists
// (NUL-separated tokens): options, values, ranges and lists. A UsageError is
// the expected answer to nonsense; anything else is a finding.
#include "CliArgs.h"

#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace shadinglab::cli;
  std::vector<std::string> tokens(1);
  for (size_t i = 0; i < size && tokens.size() < 64; ++i)
  {
    if (data[i] == 0)
    {
      tokens.emplace_back();
    }
    else
    {
      tokens.back().push_back(static_cast<char>(data[i]));
    }
  }
  std::vector<char*> argv;
  for (std::string& t : tokens)
  {
    argv.push_back(t.data());
  }
  try
  {
    Arguments args(static_cast<int>(argv.size()), argv.data(),
      { "size", "theta-l", "m", "w", "eta", "light", "max-error" }, { "stats", "quick" },
      { "light" }, { "weld" });
    for (const char* name : { "theta-l", "m", "w", "eta" })
    {
      if (args.Has(name))
      {
        (void)ParseRange(args.Get(name), std::string("--") + name, 1000);
        (void)ParseList(args.Get(name), std::string("--") + name);
      }
    }
    (void)args.GetDouble("max-error", 1.0);
    (void)args.GetInt("size", 1);
    (void)args.GetAll("light");
  }
  catch (const UsageError&)
  {
  }
  return 0;
}
