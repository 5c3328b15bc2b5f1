// SPDX-License-Identifier: BSD-3-Clause
#include "PolygonTriangulation.h"

#include <cmath>

namespace shadinglab::mesh
{

namespace
{

struct P2
{
  double x, y;
  bool operator==(const P2& o) const { return x == o.x && y == o.y; }
};

/// Twice the signed area of (a, b, c): > 0 counter-clockwise.
double Orient(const P2& a, const P2& b, const P2& c)
{
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// p in the closed triangle abc (counter-clockwise).
bool InTriangle(const P2& a, const P2& b, const P2& c, const P2& p)
{
  return Orient(a, b, p) >= 0 && Orient(b, c, p) >= 0 && Orient(c, a, p) >= 0;
}

/// Direction d leaves corner `at` strictly into the cone from `from` turning
/// counter-clockwise to `to` (a triangle's interior at that corner).
bool IntoCone(const P2& at, const P2& from, const P2& to, const P2& d)
{
  const P2 o{ at.x, at.y };
  return Orient(o, from, d) > 0 && Orient(o, d, to) > 0;
}

/// Ear clipping over a circular list (next/prev) of `live` corners.
class Clipper
{
public:
  Clipper(const std::vector<double>& x, const std::vector<double>& y)
    : N(static_cast<int64_t>(x.size()))
  {
    this->Pos.resize(x.size());
    this->Next.resize(x.size());
    this->Prev.resize(x.size());
    for (int64_t k = 0; k < N; ++k)
    {
      this->Pos[k] = { x[k], y[k] };
      this->Next[k] = (k + 1) % N;
      this->Prev[k] = (k + N - 1) % N;
    }
    this->Live = N;
  }

  void Run(std::vector<int64_t>& out)
  {
    int64_t b = 0;
    int64_t stalled = 0; // corners looked at since the last change
    while (this->Live > 3)
    {
      const int64_t a = this->Prev[b], c = this->Next[b];
      const double turn = Orient(this->Pos[a], this->Pos[b], this->Pos[c]);
      if (turn == 0)
      {
        // A repeated corner, one on a straight run, or the tip of a spike
        // back over its own edge: no area to cover.
        this->Remove(b);
        b = c;
        stalled = 0;
        continue;
      }
      if (turn > 0 && this->IsEar(a, b, c))
      {
        out.insert(out.end(), { a, b, c });
        this->Remove(b);
        b = c;
        stalled = 0;
        continue;
      }
      b = c;
      if (++stalled > this->Live)
      {
        // No ear: a non-simple polygon (or rounding). Clip the convex
        // corner of largest turn, else drop a corner, so it ends.
        this->Force(b, out);
        stalled = 0;
      }
    }
    const int64_t a = this->Prev[b], c = this->Next[b];
    if (Orient(this->Pos[a], this->Pos[b], this->Pos[c]) > 0)
    {
      out.insert(out.end(), { a, b, c });
    }
  }

private:
  /// No live corner in the closed triangle abc except those at a, b or c,
  /// and none of those lets an edge into the triangle (a slit's other side).
  bool IsEar(int64_t a, int64_t b, int64_t c) const
  {
    const P2 &A = this->Pos[a], &B = this->Pos[b], &C = this->Pos[c];
    for (int64_t p = this->Next[c]; p != a; p = this->Next[p])
    {
      const P2& q = this->Pos[p];
      if (q == A || q == B || q == C)
      {
        const P2 &before = this->Pos[this->Prev[p]], &after = this->Pos[this->Next[p]];
        for (const P2* d : { &before, &after })
        {
          if ((q == A && IntoCone(A, B, C, *d)) || (q == C && IntoCone(C, A, B, *d)) ||
            (q == B && IntoCone(B, C, A, *d)))
          {
            return false;
          }
        }
        continue;
      }
      if (InTriangle(A, B, C, q))
      {
        return false;
      }
    }
    return true;
  }

  void Force(int64_t from, std::vector<int64_t>& out)
  {
    int64_t best = -1;
    double bestTurn = 0;
    int64_t p = from;
    for (int64_t k = 0; k < this->Live; ++k, p = this->Next[p])
    {
      const double turn = Orient(this->Pos[this->Prev[p]], this->Pos[p], this->Pos[this->Next[p]]);
      if (turn > bestTurn)
      {
        best = p;
        bestTurn = turn;
      }
    }
    if (best < 0)
    {
      this->Remove(from); // nothing turns left: no area remains
      return;
    }
    out.insert(out.end(), { this->Prev[best], best, this->Next[best] });
    this->Remove(best);
  }

  void Remove(int64_t b)
  {
    this->Next[this->Prev[b]] = this->Next[b];
    this->Prev[this->Next[b]] = this->Prev[b];
    --this->Live;
  }

  int64_t N;
  int64_t Live;
  std::vector<P2> Pos;
  std::vector<int64_t> Next, Prev;
};

} // namespace

bool TriangulateCounterClockwise(
  const std::vector<double>& x, const std::vector<double>& y, std::vector<int64_t>& triangles)
{
  if (x.size() < 3 || x.size() != y.size())
  {
    return false;
  }
  for (size_t k = 0; k < x.size(); ++k)
  {
    if (!std::isfinite(x[k]) || !std::isfinite(y[k]))
    {
      return false;
    }
  }
  const size_t before = triangles.size();
  Clipper(x, y).Run(triangles);
  return triangles.size() > before;
}

} // namespace shadinglab::mesh
