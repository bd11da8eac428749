#pragma once
// Numbers items by a key of K node ids (sorted ascending, every id < node_count)
// without a global sort: a counting sort on the first id, then a small sort in
// each bucket. Equal keys get one number; numbers follow lexicographic key order.
#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace loom {

struct KeyNumbering {
  std::vector<std::uint32_t> number;  ///< per item
  std::uint32_t distinct = 0;         ///< number of distinct keys
};

/// key_of(item) returns the item's std::array<std::uint32_t, K>, sorted ascending.
template <std::size_t K, class KeyOf>
KeyNumbering number_by_key(std::size_t item_count, std::size_t node_count, KeyOf key_of) {
  std::vector<std::uint32_t> bucket_start(node_count + 1, 0);
  for (std::size_t i = 0; i < item_count; ++i) ++bucket_start[key_of(i)[0] + 1];
  for (std::size_t v = 0; v < node_count; ++v) bucket_start[v + 1] += bucket_start[v];

  std::vector<std::uint32_t> order(item_count);
  {
    std::vector<std::uint32_t> fill(bucket_start.begin(), bucket_start.end() - 1);
    for (std::size_t i = 0; i < item_count; ++i) order[fill[key_of(i)[0]]++] = static_cast<std::uint32_t>(i);
  }

  KeyNumbering result;
  result.number.resize(item_count);
  std::vector<std::pair<std::array<std::uint32_t, K>, std::uint32_t>> bucket;
  for (std::size_t v = 0; v < node_count; ++v) {
    bucket.clear();
    for (std::uint32_t at = bucket_start[v]; at < bucket_start[v + 1]; ++at)
      bucket.emplace_back(key_of(order[at]), order[at]);
    std::sort(bucket.begin(), bucket.end());
    for (std::size_t at = 0; at < bucket.size(); ++at) {
      if (at == 0 || bucket[at].first != bucket[at - 1].first) ++result.distinct;
      result.number[bucket[at].second] = result.distinct - 1;
    }
  }
  return result;
}

}  // namespace loom
