// SPDX-License-Identifier: BSD-3-Clause
// A mesh's polygon offsets or connectivity: a std::vector<int64_t> that may
// instead share memory another owner keeps alive (a VTK array), so a big
// mesh read by VTK reaches the renderer without a copy.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

namespace shadinglab::render
{

/**
 * int64 ids, read as a std::vector's are (size, data, [], begin/end).
 * Either owned (a vector) or shared: a pointer and size into memory that
 * `owner` keeps alive (MeshFromPolyDataReleasing shares vtkPolyData's
 * cell arrays: 0.5 GB and a third of a second less on 16M triangles). A
 * copy of a shared array shares too; the first change through a non-const
 * member copies a shared array into its own vector, so nothing ever
 * writes into the owner's memory.
 */
class IdArray
{
public:
  using value_type = int64_t;
  using size_type = size_t;
  using iterator = int64_t*;
  using const_iterator = const int64_t*;
  using reference = int64_t&;
  using const_reference = const int64_t&;

  IdArray() = default;
  IdArray(std::initializer_list<int64_t> ids)
    : Own(ids)
  {
  }
  IdArray(std::vector<int64_t> ids) // NOLINT: a vector is an IdArray
    : Own(std::move(ids))
  {
  }
  IdArray& operator=(std::initializer_list<int64_t> ids)
  {
    this->Own = ids;
    this->Owner.reset();
    return *this;
  }

  /// `size` ids at `data`, alive as long as `owner` is.
  static IdArray Shared(const int64_t* data, size_t size, std::shared_ptr<const void> owner)
  {
    IdArray a;
    a.SharedData = data;
    a.SharedSize = size;
    a.Owner = std::move(owner);
    return a;
  }
  bool IsShared() const { return this->Owner != nullptr; }

  size_t size() const { return this->Owner ? this->SharedSize : this->Own.size(); }
  bool empty() const { return this->size() == 0; }
  const int64_t* data() const { return this->Owner ? this->SharedData : this->Own.data(); }
  const int64_t& operator[](size_t i) const { return this->data()[i]; }
  const_iterator begin() const { return this->data(); }
  const_iterator end() const { return this->data() + this->size(); }
  const int64_t& front() const { return this->data()[0]; }
  const int64_t& back() const { return this->data()[this->size() - 1]; }

  // Changing members: a shared array becomes an owned copy first.
  int64_t* data() { return this->Mutable().data(); }
  int64_t& operator[](size_t i) { return this->Mutable()[i]; }
  iterator begin() { return this->Mutable().data(); }
  iterator end() { return this->Mutable().data() + this->Own.size(); }
  int64_t& front() { return this->Mutable().front(); }
  int64_t& back() { return this->Mutable().back(); }
  void push_back(int64_t id) { this->Mutable().push_back(id); }
  void pop_back() { this->Mutable().pop_back(); }
  void reserve(size_t n) { this->Mutable().reserve(n); }
  void resize(size_t n) { this->Mutable().resize(n); }
  void resize(size_t n, int64_t id) { this->Mutable().resize(n, id); }
  void assign(size_t n, int64_t id)
  {
    this->Owner.reset();
    this->Own.assign(n, id);
  }
  template<typename It>
  void assign(It first, It last)
  {
    std::vector<int64_t> ids(first, last); // first may point into this one
    this->Owner.reset();
    this->Own = std::move(ids);
  }
  template<typename It>
  void insert(const_iterator at, It first, It last)
  {
    const size_t offset = static_cast<size_t>(at - this->begin());
    std::vector<int64_t>& own = this->Mutable();
    own.insert(own.begin() + static_cast<std::ptrdiff_t>(offset), first, last);
  }
  void clear()
  {
    this->Owner.reset();
    this->Own.clear();
  }
  void swap(IdArray& other) noexcept
  {
    std::swap(this->Own, other.Own);
    std::swap(this->SharedData, other.SharedData);
    std::swap(this->SharedSize, other.SharedSize);
    std::swap(this->Owner, other.Owner);
  }

  friend bool operator==(const IdArray& a, const IdArray& b)
  {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
  }
  friend bool operator!=(const IdArray& a, const IdArray& b) { return !(a == b); }

private:
  std::vector<int64_t>& Mutable()
  {
    if (this->Owner)
    {
      this->Own.assign(this->SharedData, this->SharedData + this->SharedSize);
      this->Owner.reset();
      this->SharedData = nullptr;
      this->SharedSize = 0;
    }
    return this->Own;
  }

  std::vector<int64_t> Own;
  const int64_t* SharedData = nullptr;
  size_t SharedSize = 0;
  std::shared_ptr<const void> Owner;
};

} // namespace shadinglab::render
