// SPDX-License-Identifier: BSD-3-Clause
// A mesh's polygon offsets or connectivity: a std::vector<int64_t> that may
// instead share memory another owner keeps alive (a VTK array, 64-bit or
// 32-bit), so a big mesh read by VTK reaches the renderer without a copy.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

namespace shadinglab::render
{

/**
 * int64 ids, read as a std::vector's are (size, [], begin/end).
 * Either owned (a vector) or shared: a pointer and size into memory that
 * `owner` keeps alive (MeshFromPolyDataReleasing shares vtkPolyData's
 * cell arrays: 0.5 GB and a third of a second less on 16M triangles). A
 * shared array may be narrow, 32-bit ids (a vtkCellArray's 32-bit storage,
 * which the fast readers give: half the memory, 256 MB less on 16M
 * triangles); it reads as int64 all the same ([] and the iterators return
 * values), but has no int64 data(): code that wants a pointer calls Visit.
 * A copy of a shared array shares too; the first change through a
 * non-const member copies a shared array into its own (int64) vector, so
 * nothing ever writes into the owner's memory.
 */
class IdArray
{
public:
  using value_type = int64_t;
  using size_type = size_t;
  using iterator = int64_t*;
  using reference = int64_t&;
  using const_reference = int64_t;

  /// Reads either width as int64 values (a random-access iterator).
  class const_iterator
  {
  public:
    using iterator_category = std::random_access_iterator_tag;
    using value_type = int64_t;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = int64_t;

    const_iterator() = default;
    const_iterator(const int64_t* wide, const int32_t* narrow, std::ptrdiff_t i)
      : Wide(wide)
      , Narrow(narrow)
      , I(i)
    {
    }
    int64_t operator*() const { return this->Narrow ? this->Narrow[this->I] : this->Wide[this->I]; }
    int64_t operator[](std::ptrdiff_t k) const { return *(*this + k); }
    const_iterator& operator++() { ++this->I; return *this; }
    const_iterator operator++(int) { const_iterator c = *this; ++this->I; return c; }
    const_iterator& operator--() { --this->I; return *this; }
    const_iterator operator--(int) { const_iterator c = *this; --this->I; return c; }
    const_iterator& operator+=(std::ptrdiff_t k) { this->I += k; return *this; }
    const_iterator& operator-=(std::ptrdiff_t k) { this->I -= k; return *this; }
    friend const_iterator operator+(const_iterator a, std::ptrdiff_t k) { return a += k; }
    friend const_iterator operator+(std::ptrdiff_t k, const_iterator a) { return a += k; }
    friend const_iterator operator-(const_iterator a, std::ptrdiff_t k) { return a -= k; }
    friend std::ptrdiff_t operator-(const const_iterator& a, const const_iterator& b) { return a.I - b.I; }
    friend bool operator==(const const_iterator& a, const const_iterator& b) { return a.I == b.I; }
    friend bool operator!=(const const_iterator& a, const const_iterator& b) { return a.I != b.I; }
    friend bool operator<(const const_iterator& a, const const_iterator& b) { return a.I < b.I; }
    friend bool operator>(const const_iterator& a, const const_iterator& b) { return a.I > b.I; }
    friend bool operator<=(const const_iterator& a, const const_iterator& b) { return a.I <= b.I; }
    friend bool operator>=(const const_iterator& a, const const_iterator& b) { return a.I >= b.I; }

  private:
    const int64_t* Wide = nullptr;
    const int32_t* Narrow = nullptr;
    std::ptrdiff_t I = 0;
  };

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
    this->Drop();
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
  /// `size` 32-bit ids at `data`, alive as long as `owner` is.
  static IdArray SharedNarrow(const int32_t* data, size_t size, std::shared_ptr<const void> owner)
  {
    IdArray a;
    a.NarrowData = data;
    a.SharedSize = size;
    a.Owner = std::move(owner);
    return a;
  }
  bool IsShared() const { return this->Owner != nullptr; }
  bool IsNarrow() const { return this->NarrowData != nullptr; }

  size_t size() const { return this->Owner ? this->SharedSize : this->Own.size(); }
  bool empty() const { return this->size() == 0; }
  /// The ids as int64_t in place; null for a narrow array (see Visit).
  const int64_t* data() const { return this->Owner ? this->SharedData : this->Own.data(); }
  /// The 32-bit ids of a narrow array in place; null for a wide one.
  const int32_t* narrowData() const { return this->NarrowData; }
  /// f(ids) with the ids in place, as `const int64_t*` or (narrow) `const
  /// int32_t*`: for loops that take a pointer (f must return the same type
  /// for both).
  template <typename F>
  decltype(auto) Visit(F&& f) const
  {
    return this->NarrowData ? f(this->NarrowData) : f(this->data());
  }
  /// The bytes the ids take in place (a hash's input), and their count.
  const void* Bytes() const
  {
    return this->NarrowData ? static_cast<const void*>(this->NarrowData)
                            : static_cast<const void*>(this->data());
  }
  size_t ByteSize() const { return this->size() * (this->NarrowData ? 4 : 8); }
  /// Where id i is held (a prefetch's address), either width.
  const void* AddressOf(size_t i) const
  {
    return this->NarrowData ? static_cast<const void*>(this->NarrowData + i)
                            : static_cast<const void*>(this->data() + i);
  }
  int64_t operator[](size_t i) const
  {
    return this->NarrowData ? this->NarrowData[i] : this->data()[i];
  }
  const_iterator begin() const { return const_iterator(this->data(), this->NarrowData, 0); }
  const_iterator end() const
  {
    return const_iterator(
      this->data(), this->NarrowData, static_cast<std::ptrdiff_t>(this->size()));
  }
  int64_t front() const { return (*this)[0]; }
  int64_t back() const { return (*this)[this->size() - 1]; }

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
    this->Drop();
    this->Own.assign(n, id);
  }
  template<typename It>
  void assign(It first, It last)
  {
    std::vector<int64_t> ids(first, last); // first may point into this one
    this->Drop();
    this->Own = std::move(ids);
  }
  template<typename It>
  void insert(const_iterator at, It first, It last)
  {
    const size_t offset = static_cast<size_t>(at - static_cast<const IdArray&>(*this).begin());
    std::vector<int64_t>& own = this->Mutable();
    own.insert(own.begin() + static_cast<std::ptrdiff_t>(offset), first, last);
  }
  void clear()
  {
    this->Drop();
    this->Own.clear();
  }
  void swap(IdArray& other) noexcept
  {
    std::swap(this->Own, other.Own);
    std::swap(this->SharedData, other.SharedData);
    std::swap(this->NarrowData, other.NarrowData);
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
      if (this->NarrowData)
      {
        this->Own.assign(this->NarrowData, this->NarrowData + this->SharedSize);
      }
      else
      {
        this->Own.assign(this->SharedData, this->SharedData + this->SharedSize);
      }
      this->Drop();
    }
    return this->Own;
  }
  /// Forgets the shared memory (the owned vector is left as it is).
  void Drop()
  {
    this->Owner.reset();
    this->SharedData = nullptr;
    this->NarrowData = nullptr;
    this->SharedSize = 0;
  }

  std::vector<int64_t> Own;
  const int64_t* SharedData = nullptr;
  const int32_t* NarrowData = nullptr;
  size_t SharedSize = 0;
  std::shared_ptr<const void> Owner;
};

} // namespace shadinglab::render
