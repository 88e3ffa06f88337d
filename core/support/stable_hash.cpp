#include "core/support/stable_hash.h"

#include <xxhash.h>

namespace triwalk {

void StableHash::addBytes(std::span<const std::byte> bytes) {
  // Seeding each part's hash with the value so far chains the parts
  // without keeping XXH3's streaming state.
  hash_ = XXH3_64bits_withSeed(bytes.data(), bytes.size(), hash_);
}

}  // namespace triwalk
