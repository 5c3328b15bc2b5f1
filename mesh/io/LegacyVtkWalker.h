// SPDX-License-Identifier: BSD-3-Clause
// The reader under LegacyVtkCheck.cxx: it walks a legacy .vtk file the way
// vtkDataReader reads it (tokens separated by C-locale white space, header
// lines, big-endian binary blocks after the rest of their header line) and
// checks each value's syntax and type, allocating nothing proportional to a
// count in the file. Every problem is a MeshError naming it and its line
// (or byte offset in a binary file).
#pragma once

#include "MeshIO.h"
#include "PrecheckCommon.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace shadinglab
{
namespace legacy_vtk
{

/// Longest token or header line vtkDataReader handles as one: ReadString
/// and ReadLine read into char[256]; a longer token is split by VTK and
/// the rest read as the next keyword, so the walk would no longer match.
constexpr size_t kMaxTokenLength = 255;

using precheck::kMaxElementCount;
using precheck::ParseInteger;

struct ValueType
{
  const char* name;
  int size;
  bool integer;
};

/// The numeric types vtkDataReader::ReadArray reads, with their size in a
/// binary file (big-endian; "long" is 8 bytes on LP64 Linux).
constexpr ValueType kValueTypes[] = { { "unsigned_char", 1, true },
  { "char", 1, true },
  { "signed_char", 1, true },
  { "unsigned_short", 2, true },
  { "short", 2, true },
  { "unsigned_int", 4, true },
  { "int", 4, true },
  { "unsigned_long", 8, true },
  { "long", 8, true },
  { "vtktypeint64", 8, true },
  { "vtktypeuint64", 8, true },
  { "vtkidtype", 8, true },
  { "float", 4, false },
  { "double", 8, false } };
constexpr const ValueType& kUnsignedChar = kValueTypes[0];
constexpr const ValueType& kInt = kValueTypes[6];
constexpr const ValueType& kFloat = kValueTypes[12];

inline std::string Lower(std::string s)
{
  std::transform(s.begin(),
    s.end(),
    s.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// A buffered reader that walks the file as vtkDataReader does: tokens
/// separated by C-locale white space, header lines, and binary blocks.
class Walker
{
public:
  Walker(const std::string& path)
    : Path(path)
    , Buffer(1 << 20)
  {
    this->File = std::fopen(path.c_str(), "rb");
    if (!this->File)
    {
      throw MeshError("cannot open '" + path + "' (no permission?)");
    }
  }
  ~Walker() { std::fclose(this->File); }
  Walker(const Walker&) = delete;
  Walker& operator=(const Walker&) = delete;

  [[noreturn]] void Fail(const std::string& what) const
  {
    throw MeshError("malformed VTK file '" + this->Path + "': " + what +
      (this->Binary ? " (near byte " + std::to_string(this->Offset()) + ")"
                    : " (line " + std::to_string(this->Line) + ")"));
  }

  long long Offset() const { return this->Consumed + static_cast<long long>(this->Pos); }

  int Peek()
  {
    if (this->Pos == this->Length && !this->Refill())
    {
      return EOF;
    }
    return static_cast<unsigned char>(this->Buffer[this->Pos]);
  }
  int Get()
  {
    const int c = this->Peek();
    if (c != EOF)
    {
      ++this->Pos;
      this->Line += c == '\n';
    }
    return c;
  }

  /// The next white-space separated token, or false at the end of file.
  /// The white space after it stays unread, as `istream >> char[]` leaves
  /// it: a binary block starts after the rest of its header line.
  bool Token(std::string& token)
  {
    token.clear();
    while (this->Peek() != EOF && std::isspace(this->Peek()))
    {
      this->Get();
    }
    while (this->Peek() != EOF && !std::isspace(this->Peek()))
    {
      const int c = this->Get();
      if (c == '\0' || token.size() == kMaxTokenLength)
      {
        this->Fail(
          c == '\0' ? "a NUL byte in a keyword or value" : "a token longer than 255 characters");
      }
      token.push_back(static_cast<char>(c));
    }
    return !token.empty();
  }

  /// `count` numbers written as text even in a binary file (DIMENSIONS,
  /// SPACING, ORIGIN are header values).
  void TextReals(const std::string& what, int count)
  {
    for (int i = 0; i < count; ++i)
    {
      const std::string token = this->Expect(what.c_str());
      if (!IsReal(token))
      {
        this->Fail(what + ": '" + token + "' is not a number");
      }
    }
  }

  std::string Expect(const char* what)
  {
    std::string token;
    if (!this->Token(token))
    {
      this->Fail("the file ends where " + std::string(what) + " was expected (truncated?)");
    }
    return token;
  }

  /// The rest of the current line without its newline (and a trailing CR).
  std::string RestOfLine(bool limit = true)
  {
    std::string line;
    for (int c = this->Get(); c != EOF && c != '\n'; c = this->Get())
    {
      if (line.size() < kMaxTokenLength + 1)
      {
        line.push_back(static_cast<char>(c));
      }
      else if (limit)
      {
        this->Fail("a line longer than 255 characters");
      }
    }
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    return line;
  }

  long long Count(const std::string& what, long long low = 0, long long high = kMaxElementCount)
  {
    const std::string token = this->Expect(what.c_str());
    long long value = 0;
    if (!ParseInteger(token, value) || value < low || value > high)
    {
      this->Fail(what + " '" + token + "' (an integer in [" + std::to_string(low) + ", " +
        std::to_string(high) + "] expected)");
    }
    return value;
  }

  const ValueType& Type(const std::string& what)
  {
    const std::string token = this->Expect((what + " type").c_str());
    const std::string lower = Lower(token);
    for (const ValueType& t : kValueTypes)
    {
      if (lower == t.name)
      {
        return t;
      }
    }
    this->Fail(what + ": value type '" + token +
      "' is not read (numeric types only: no string, bit or variant arrays)");
  }

  /// `count` values of `type`. In a binary file the block follows the rest
  /// of the header line; `visit` sees each value when it is an integer.
  template<typename Visit>
  void Values(const std::string& what, long long count, const ValueType& type, Visit visit)
  {
    if (this->Binary)
    {
      this->RestOfLine();
      const long long bytes = count * type.size;
      if (bytes > this->FileSize - this->Offset())
      {
        this->Fail(what + ": " + std::to_string(count) + " values need " + std::to_string(bytes) +
          " bytes; the file has " + std::to_string(this->FileSize - this->Offset()) +
          " left (truncated?)");
      }
      if (!type.integer)
      {
        this->Skip(bytes);
        return;
      }
      unsigned char item[8];
      for (long long i = 0; i < count; ++i)
      {
        for (int b = 0; b < type.size; ++b)
        {
          item[b] = static_cast<unsigned char>(this->Get());
        }
        visit(i, precheck::ReadInteger(item, type.size, type.name[0] != 'u', true));
      }
      return;
    }
    // Each text value takes at least two bytes ("0 "): refuse a count the
    // file cannot hold before walking it.
    if (count > (this->FileSize - this->Offset() + 1) / 2)
    {
      this->Fail(what + ": " + std::to_string(count) + " values cannot fit in the " +
        std::to_string(this->FileSize - this->Offset()) + " bytes left (truncated?)");
    }
    std::string token;
    for (long long i = 0; i < count; ++i)
    {
      if (!this->Token(token))
      {
        this->Fail(what + ": the file ends after " + std::to_string(i) + " of " +
          std::to_string(count) + " values (truncated?)");
      }
      if (type.integer)
      {
        long long value = 0;
        if (!ParseInteger(token, value))
        {
          this->Fail(what + ": value " + std::to_string(i) + " '" + token + "' is not an integer");
        }
        visit(i, value);
      }
      else if (!IsReal(token))
      {
        this->Fail(what + ": value " + std::to_string(i) + " '" + token + "' is not a number");
      }
    }
  }

  void Values(const std::string& what, long long count, const ValueType& type)
  {
    this->Values(what, count, type, [](long long, long long) {});
  }

  /// What `istream >> double` reads whole: [+-] digits [. digits] [e [+-] digits].
  static bool IsReal(const std::string& t)
  {
    size_t i = t[0] == '+' || t[0] == '-' ? 1 : 0;
    size_t digits = 0;
    while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])))
    {
      ++i, ++digits;
    }
    if (i < t.size() && t[i] == '.')
    {
      ++i;
      while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])))
      {
        ++i, ++digits;
      }
    }
    if (digits == 0)
    {
      return false;
    }
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E'))
    {
      ++i;
      i += i < t.size() && (t[i] == '+' || t[i] == '-');
      size_t exponent = 0;
      while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])))
      {
        ++i, ++exponent;
      }
      if (exponent == 0)
      {
        return false;
      }
    }
    return i == t.size();
  }

  std::string Path;
  FILE* File = nullptr;
  std::vector<char> Buffer;
  size_t Pos = 0, Length = 0;
  long long Consumed = 0, Line = 1, FileSize = 0;
  bool Binary = false;

private:
  void Skip(long long bytes)
  {
    while (bytes > 0)
    {
      if (this->Pos == this->Length && !this->Refill())
      {
        return;
      }
      const long long step =
        std::min<long long>(bytes, static_cast<long long>(this->Length - this->Pos));
      this->Pos += static_cast<size_t>(step);
      bytes -= step;
    }
  }

  bool Refill()
  {
    this->Consumed += static_cast<long long>(this->Length);
    this->Length = std::fread(this->Buffer.data(), 1, this->Buffer.size(), this->File);
    this->Pos = 0;
    return this->Length > 0;
  }
};

} // namespace legacy_vtk
} // namespace shadinglab
