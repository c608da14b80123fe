#include "io/checkpoint_codec.hpp"

#include <fmt/format.h>

namespace heliostand::checkpoint {

const char* Reader::take(std::size_t n, const char* what) {
  if (n > bytes_.size() - offset_)
    throw CheckpointError(fmt::format("ends early: {} needs {} bytes at byte {} of the payload, {} left", what, n,
                                      offset_, bytes_.size() - offset_));
  const char* start = bytes_.data() + offset_;
  offset_ += n;
  return start;
}

std::size_t Reader::size(const char* what, std::size_t item_bytes) {
  const auto n = raw<std::uint64_t>(what);
  const std::size_t left = bytes_.size() - offset_;
  if (n > left / (item_bytes == 0 ? 1 : item_bytes))
    throw CheckpointError(fmt::format("{} claims {} items at byte {} of the payload, more than the {} bytes left",
                                      what, n, offset_, left));
  return static_cast<std::size_t>(n);
}

std::string Reader::text(const char* what) {
  const std::size_t n = size(what);
  return std::string(take(n, what), n);
}

std::vector<bool> Reader::bools(const char* what) {
  std::vector<bool> values(size(what));
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = raw<std::uint8_t>(what) != 0;
  return values;
}

}  // namespace heliostand::checkpoint
