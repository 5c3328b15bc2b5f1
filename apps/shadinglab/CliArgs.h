// SPDX-License-Identifier: BSD-3-Clause
// Command-line parsing shared by the shadinglab subcommands. Every parse
// failure throws UsageError with a one-line message; main() prints it and
// exits with status 2.
#pragma once

#include <chrono>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace shadinglab::cli
{

/// Wall time since construction, for the commands' phase breakdowns
/// (`render --stats`, `normals --json`: read, prepare, render, write).
class Stopwatch
{
public:
  double Milliseconds() const
  {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - this->Start)
      .count();
  }

private:
  std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();
};

/// The process's peak resident memory so far, in MB (getrusage's
/// ru_maxrss): read after each stage, the --stats memory by stage.
double PeakRssMb();

/// The process's peak resident memory so far, in MB (getrusage).
double PeakResidentMB();

struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Options of the form --name value or --name (flag), plus positionals.
class Arguments
{
public:
  /// @param flags option names that take no value (e.g. "stats").
  /// @param repeatable valued options that may be given more than once.
  /// @param optionalNumber options whose value is optional: a following
  ///   token is taken as the value only when it is a number.
  Arguments(int argc, char** argv, const std::vector<std::string>& valued,
    const std::vector<std::string>& flags, const std::vector<std::string>& repeatable = {},
    const std::vector<std::string>& optionalNumber = {});

  bool Has(const std::string& name) const { return this->Values.count(name) > 0; }
  std::string Get(const std::string& name, const std::string& fallback = {}) const;
  double GetDouble(const std::string& name, double fallback) const;
  int GetInt(const std::string& name, int fallback) const;
  const std::vector<std::string>& Positionals() const { return this->Positional; }
  /// Every value of a repeatable option, in command-line order.
  std::vector<std::string> GetAll(const std::string& name) const;

private:
  std::map<std::string, std::string> Values;
  std::map<std::string, std::vector<std::string>> Repeated;
  std::vector<std::string> Positional;
};

/// A finite double, or UsageError naming the option.
double ParseDouble(const std::string& text, const std::string& what);
/// Comma-separated finite doubles.
std::vector<double> ParseList(const std::string& text, const std::string& what);
/// A value, a comma list, or START:STOP:STEP (inclusive, STEP > 0).
/// At most maxCount values.
std::vector<double> ParseRange(const std::string& text, const std::string& what, size_t maxCount);

} // namespace shadinglab::cli
