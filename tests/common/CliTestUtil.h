// SPDX-License-Identifier: BSD-3-Clause
// Runs the real shadinglab binary and captures exit status, stdout, stderr.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace shadinglab::testing
{

struct RunResult
{
  int status = -1;
  std::string out;
  std::string err;
};

/// A path in gtest's TempDir() named after the running test: ctest runs
/// each TEST as its own process, in parallel, and a file name shared by
/// several tests could be rewritten while another reads it.
inline std::string PerTestTempPath(const std::string& stem, const std::string& extension)
{
  return ::testing::TempDir() + "/" + stem + "_" +
    ::testing::UnitTest::GetInstance()->current_test_info()->name() + extension;
}

/// Runs `prefix shadinglab arguments` (prefix e.g. "env -u DISPLAY ").
inline RunResult RunCli(const std::string& arguments, const std::string& prefix = {})
{
  char errPath[] = "/tmp/shadinglab_cli_stderr_XXXXXX";
  const int fd = mkstemp(errPath);
  close(fd);
  const std::string command =
    prefix + std::string(SHADINGLAB_CLI) + " " + arguments + " 2>" + errPath;
  RunResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe)
  {
    return result;
  }
  char buffer[4096];
  size_t n = 0;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0)
  {
    result.out.append(buffer, n);
  }
  const int raw = pclose(pipe);
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  std::ifstream errFile(errPath);
  std::stringstream ss;
  ss << errFile.rdbuf();
  result.err = ss.str();
  std::remove(errPath);
  return result;
}

inline int CountLines(const std::string& text)
{
  int n = 0;
  for (char c : text)
  {
    n += c == '\n';
  }
  return n;
}

} // namespace shadinglab::testing
