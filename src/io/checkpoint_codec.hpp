#pragma once
// The byte encoding of a checkpoint's payload (docs/formats.md "Checkpoints"): numbers and plain structs are
// written as their raw bytes, so a double comes back bit for bit (text would round); strings and vectors are a
// 64-bit length followed by their contents. The reader checks every length against what is left, so a cut-off or
// damaged payload ends in a CheckpointError naming what was being read, never in a crash or a huge allocation.
// Raw structs tie the encoding to this build's layout: the file header carries the program version and a layout
// fingerprint (io/checkpoint_file.hpp), and a checkpoint of another build is refused as foreign.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace heliostand::checkpoint {

class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

template <typename T>
inline constexpr bool is_raw = std::is_trivially_copyable_v<T> && !std::is_pointer_v<T>;

class Writer {
 public:
  template <typename T>
  void raw(const T& value) {
    static_assert(is_raw<T>, "only plain values are written as bytes");
    const auto* bytes = reinterpret_cast<const char*>(&value);
    bytes_.append(bytes, sizeof(T));
  }
  void size(std::size_t n) { raw(static_cast<std::uint64_t>(n)); }
  void text(std::string_view s) {
    size(s.size());
    bytes_.append(s.data(), s.size());
  }
  template <typename T>
  void raw_vector(const std::vector<T>& values) {
    static_assert(is_raw<T>, "only vectors of plain values are written as bytes");
    size(values.size());
    bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  void bools(const std::vector<bool>& values) {
    size(values.size());
    for (bool b : values) raw(static_cast<std::uint8_t>(b));
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}

  template <typename T>
  T raw(const char* what) {
    static_assert(is_raw<T>, "only plain values are read as bytes");
    T value;
    std::memcpy(static_cast<void*>(&value), take(sizeof(T), what), sizeof(T));
    return value;
  }
  template <typename T>
  void raw_into(T& value, const char* what) { value = raw<T>(what); }
  // A count of items of `item_bytes` each: never more than the bytes left could hold.
  std::size_t size(const char* what, std::size_t item_bytes = 1);
  std::string text(const char* what);
  template <typename T>
  std::vector<T> raw_vector(const char* what) {
    static_assert(is_raw<T>, "only vectors of plain values are read as bytes");
    std::vector<T> values(size(what, sizeof(T)));
    if (!values.empty()) std::memcpy(static_cast<void*>(values.data()), take(values.size() * sizeof(T), what),
                                     values.size() * sizeof(T));
    return values;
  }
  std::vector<bool> bools(const char* what);
  bool at_end() const { return offset_ == bytes_.size(); }
  std::size_t offset() const { return offset_; }

 private:
  const char* take(std::size_t n, const char* what);

  std::string_view bytes_;
  std::size_t offset_ = 0;
};

}  // namespace heliostand::checkpoint
