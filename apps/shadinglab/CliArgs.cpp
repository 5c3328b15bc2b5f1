// SPDX-License-Identifier: BSD-3-Clause
#include "CliArgs.h"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace shadinglab::cli
{

double PeakRssMb()
{
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0; // KB on Linux
}

double PeakResidentMB()
{
  struct rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0; // kilobytes on Linux
}

Arguments::Arguments(int argc, char** argv, const std::vector<std::string>& valued,
  const std::vector<std::string>& flags, const std::vector<std::string>& repeatable,
  const std::vector<std::string>& optionalNumber)
{
  for (int i = 0; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg.size() > 2 && arg.compare(0, 2, "--") == 0)
    {
      std::string name = arg.substr(2);
      std::string value;
      bool inlineValue = false;
      const auto eq = name.find('=');
      if (eq != std::string::npos)
      {
        value = name.substr(eq + 1);
        name = name.substr(0, eq);
        inlineValue = true;
      }
      if (std::find(optionalNumber.begin(), optionalNumber.end(), name) != optionalNumber.end())
      {
        if (!inlineValue && i + 1 < argc)
        {
          char* end = nullptr;
          std::strtod(argv[i + 1], &end);
          if (end != argv[i + 1] && *end == '\0')
          {
            value = argv[++i];
          }
        }
        this->Values[name] = value;
        continue;
      }
      if (std::find(flags.begin(), flags.end(), name) != flags.end())
      {
        if (inlineValue)
        {
          throw UsageError("option --" + name + " takes no value");
        }
        this->Values[name] = "1";
        continue;
      }
      const bool isRepeatable =
        std::find(repeatable.begin(), repeatable.end(), name) != repeatable.end();
      if (!isRepeatable && std::find(valued.begin(), valued.end(), name) == valued.end())
      {
        throw UsageError("unknown option --" + name);
      }
      if (!inlineValue)
      {
        if (i + 1 >= argc)
        {
          throw UsageError("option --" + name + " needs a value");
        }
        value = argv[++i];
      }
      if (isRepeatable)
      {
        this->Repeated[name].push_back(value);
        this->Values[name] = value;
        continue;
      }
      if (this->Values.count(name))
      {
        throw UsageError("option --" + name + " given twice");
      }
      this->Values[name] = value;
    }
    else
    {
      this->Positional.push_back(arg);
    }
  }
}

std::string Arguments::Get(const std::string& name, const std::string& fallback) const
{
  const auto it = this->Values.find(name);
  return it == this->Values.end() ? fallback : it->second;
}

std::vector<std::string> Arguments::GetAll(const std::string& name) const
{
  const auto it = this->Repeated.find(name);
  return it == this->Repeated.end() ? std::vector<std::string>{} : it->second;
}

double Arguments::GetDouble(const std::string& name, double fallback) const
{
  return this->Has(name) ? ParseDouble(this->Get(name), "--" + name) : fallback;
}

int Arguments::GetInt(const std::string& name, int fallback) const
{
  if (!this->Has(name))
  {
    return fallback;
  }
  const double v = ParseDouble(this->Get(name), "--" + name);
  if (v != std::floor(v) || std::abs(v) > 1e9)
  {
    throw UsageError("--" + name + " must be an integer (got '" + this->Get(name) + "')");
  }
  return static_cast<int>(v);
}

double ParseDouble(const std::string& text, const std::string& what)
{
  if (text.empty())
  {
    throw UsageError(what + ": empty number");
  }
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0')
  {
    throw UsageError(what + ": '" + text + "' is not a number");
  }
  if (!std::isfinite(v))
  {
    throw UsageError(what + ": '" + text + "' is not finite");
  }
  return v;
}

std::vector<double> ParseList(const std::string& text, const std::string& what)
{
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ','))
  {
    out.push_back(ParseDouble(item, what));
  }
  if (out.empty() || (!text.empty() && text.back() == ','))
  {
    throw UsageError(what + ": '" + text + "' is not a comma-separated list of numbers");
  }
  return out;
}

std::vector<double> ParseRange(const std::string& text, const std::string& what, size_t maxCount)
{
  if (std::count(text.begin(), text.end(), ':') == 2)
  {
    const auto c1 = text.find(':');
    const auto c2 = text.find(':', c1 + 1);
    const double start = ParseDouble(text.substr(0, c1), what);
    const double stop = ParseDouble(text.substr(c1 + 1, c2 - c1 - 1), what);
    const double step = ParseDouble(text.substr(c2 + 1), what);
    if (!(step > 0.0))
    {
      throw UsageError(what + ": STEP must be > 0 in START:STOP:STEP (got '" + text + "')");
    }
    if (stop < start)
    {
      throw UsageError(what + ": STOP must be >= START in START:STOP:STEP (got '" + text + "')");
    }
    // Inclusive of STOP up to a relative rounding slack of 1e-9 steps, so
    // 0:90:5 yields 19 values despite binary rounding of the step.
    const double n = std::floor((stop - start) / step + 1e-9);
    if (n + 1.0 > static_cast<double>(maxCount))
    {
      throw UsageError(what + ": range '" + text + "' has more than " +
        std::to_string(maxCount) + " values");
    }
    std::vector<double> out;
    for (int i = 0; i <= static_cast<int>(n); ++i)
    {
      out.push_back(start + i * step);
    }
    return out;
  }
  if (text.find(':') != std::string::npos)
  {
    throw UsageError(what + ": '" + text + "' is neither a value, a list nor START:STOP:STEP");
  }
  auto out = ParseList(text, what);
  if (out.size() > maxCount)
  {
    throw UsageError(what + ": more than " + std::to_string(maxCount) + " values");
  }
  return out;
}

} // namespace shadinglab::cli
