// SPDX-License-Identifier: BSD-3-Clause
// The renderer's per-mesh caches and their one rule: what costs a pass over
// the mesh is built on the second frame a mesh (its content hash,
// render::Mesh::ContentHash) is drawn, so that a renderer drawing a mesh
// once (the CLI) does not pay for what that frame cannot earn back, and one
// redrawing it (the explorer, ParaView) pays once.
#pragma once

#include <cstdint>
#include <optional>

namespace shadinglab::cpu
{

/// Remembers the last mesh asked about.
class SecondSighting
{
public:
  /// Whether the previous call was for the same mesh; remembers this one.
  bool SeenBefore(uint64_t fingerprint)
  {
    const bool seen = this->Last == fingerprint;
    this->Last = fingerprint;
    return seen;
  }

private:
  std::optional<uint64_t> Last;
};

/// A value made from the last mesh drawn, from its second frame on.
template <typename T>
class SecondFrameCache
{
public:
  /// The value for the mesh `fingerprint`, made by build(T&) on the mesh's
  /// second frame in a row and kept while it is drawn; nullptr before.
  template <typename Build>
  const T* Get(uint64_t fingerprint, Build&& build)
  {
    if (this->For != fingerprint)
    {
      if (!this->Sightings.SeenBefore(fingerprint))
      {
        return nullptr;
      }
      build(this->Value);
      this->For = fingerprint;
    }
    return &this->Value;
  }

private:
  std::optional<uint64_t> For; ///< the mesh Value is for
  SecondSighting Sightings;
  T Value{};
};

} // namespace shadinglab::cpu
