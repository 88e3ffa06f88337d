#pragma once
// A 64-bit hash that is the same on every run and machine, for the keys
// and checksums of the data set's stores (core/io/derived_files.h). It is
// XXH3 (xxHash), which hashes several gigabytes a second: the store of
// downsampled panoramas keys each copy by the whole EXR file it was made
// from, 2.3 MB a view, which a byte-at-a-time hash would take longer to
// read than OpenEXR takes to decode.

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

namespace triwalk {

class StableHash {
public:
  // Each call continues the hash: the same calls with the same bytes give
  // the same value.
  void addBytes(std::span<const std::byte> bytes);
  template <typename T>
  void addValue(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "hash the bytes of plain values only");
    addBytes(std::as_bytes(std::span<const T>(&value, 1)));
  }
  uint64_t value() const { return hash_; }

private:
  uint64_t hash_ = 0;
};

}  // namespace triwalk
