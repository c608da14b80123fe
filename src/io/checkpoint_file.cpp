#include "io/checkpoint_file.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>

#include <fmt/format.h>

#include "io/output_folder.hpp"

namespace heliostand::checkpoint {
namespace fs = std::filesystem;
namespace {

std::uint32_t crc32_of(std::string_view bytes) {
  const uLong start = crc32_z(0L, Z_NULL, 0);
  return static_cast<std::uint32_t>(crc32_z(start, reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
}

const std::regex& checkpoint_name() {
  static const std::regex pattern("checkpoint_year_([0-9]{4,})\\.hsck");
  return pattern;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError("cannot be opened");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return std::move(bytes).str();
}

// Opens, fsyncs and closes `path` (a file or a folder); throws OutputFolderError on failure.
void fsync_path(const fs::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) throw OutputFolderError(fmt::format("cannot open {} to sync it: {}", path.string(), std::strerror(errno)));
  const int synced = ::fsync(fd);
  const int error = errno;
  ::close(fd);
  if (synced != 0) throw OutputFolderError(fmt::format("cannot sync {}: {}", path.string(), std::strerror(error)));
}

void write_all(int fd, std::string_view bytes, const fs::path& path) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) throw OutputFolderError(fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
}

std::string encode(const CheckpointFile& file) {
  Writer out;
  out.raw(magic);
  out.raw(format_version);
  out.raw(static_cast<std::int32_t>(file.years_done));
  out.size(file.identity.entries.size());
  for (const auto& [key, value] : file.identity.entries) {
    out.text(key);
    out.text(value);
  }
  out.text(file.payload);
  std::string bytes = out.bytes();
  const std::uint32_t crc = crc32_of(bytes);
  bytes.append(reinterpret_cast<const char*>(&crc), sizeof crc);
  return bytes;
}

}  // namespace

std::string RunIdentity::difference_from(const RunIdentity& other) const {
  for (const auto& entry : entries) {
    const std::string& key = entry.first;  // a named variable: clang 14 cannot capture a structured binding
    const std::string& value = entry.second;
    const auto theirs = std::find_if(other.entries.begin(), other.entries.end(),
                                     [&key](const auto& candidate) { return candidate.first == key; });
    if (theirs == other.entries.end()) return fmt::format("it records no {}", key);
    if (theirs->second != value)
      return fmt::format("its {} is {}, this run's is {}", key, theirs->second, value);
  }
  return {};
}

std::string file_name_for_year(int years_done) { return fmt::format("checkpoint_year_{:04d}.hsck", years_done); }

fs::path write_checkpoint(const fs::path& folder, const CheckpointFile& file) {
  const fs::path final_path = folder / file_name_for_year(file.years_done);
  const fs::path temporary = temporary_sibling(final_path);
  const std::string bytes = encode(file);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    throw OutputFolderError(fmt::format("cannot write {}: {}", temporary.string(), std::strerror(errno)));
  try {
    write_all(fd, bytes, temporary);
    if (::fsync(fd) != 0)
      throw OutputFolderError(fmt::format("cannot sync {}: {}", temporary.string(), std::strerror(errno)));
  } catch (...) {
    ::close(fd);
    fs::remove(temporary);
    throw;
  }
  ::close(fd);
  std::error_code error;
  fs::rename(temporary, final_path, error);
  if (error)
    throw OutputFolderError(fmt::format("cannot rename {} to {}: {}", temporary.string(), final_path.string(),
                                        error.message()));
  fsync_path(folder, O_RDONLY | O_DIRECTORY);  // the rename itself survives a crash of the machine
  return final_path;
}

CheckpointFile read_checkpoint(const fs::path& path, const RunIdentity& expected) {
  const std::string bytes = read_bytes(path);
  Reader in(bytes);
  if (bytes.size() < sizeof magic || std::memcmp(bytes.data(), magic, sizeof magic) != 0)
    throw CheckpointError("is not a heliostand checkpoint (no HSCHKPT1 magic at its start)");
  in.raw<std::array<char, sizeof magic>>("magic");
  const auto version = in.raw<std::uint32_t>("format version");
  if (version != format_version)
    throw CheckpointError(fmt::format("is format version {}; this heliostand reads version {} only (foreign)",
                                      version, format_version));
  CheckpointFile file;
  try {
    file.years_done = in.raw<std::int32_t>("years done");
    const std::size_t entries = in.size("run identity", 16);
    for (std::size_t k = 0; k < entries; ++k) {
      std::string key = in.text("run identity key");
      file.identity.add(std::move(key), in.text("run identity value"));
    }
    file.payload = in.text("payload");
    const std::size_t checked = in.offset();
    const auto crc = in.raw<std::uint32_t>("checksum");
    if (!in.at_end()) throw CheckpointError(fmt::format("has {} bytes after its checksum", bytes.size() - in.offset()));
    if (crc != crc32_of(std::string_view(bytes).substr(0, checked)))
      throw CheckpointError(fmt::format("is damaged: its CRC-32 is {:08x}, its contents' {:08x}", crc,
                                        crc32_of(std::string_view(bytes).substr(0, checked))));
  } catch (const CheckpointError& e) {
    const std::string reason = e.what();
    if (reason.rfind("ends early", 0) == 0 || reason.find("claims") != std::string::npos)
      throw CheckpointError(fmt::format("is truncated or damaged ({} bytes): {}", bytes.size(), reason));
    throw;
  }
  if (const std::string difference = expected.difference_from(file.identity); !difference.empty())
    throw CheckpointError(fmt::format("belongs to another run (foreign): {}", difference));
  return file;
}

std::vector<fs::path> checkpoints_in(const fs::path& folder) {
  std::vector<std::pair<long, fs::path>> found;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
    std::smatch match;
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && std::regex_match(name, match, checkpoint_name()))
      found.emplace_back(std::stol(match[1].str()), entry.path());
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<fs::path> paths;
  for (auto& [year, path] : found) paths.push_back(std::move(path));
  return paths;
}

void prune_checkpoints(const fs::path& folder, std::size_t keep) {
  const auto all = checkpoints_in(folder);
  for (std::size_t k = keep; k < all.size(); ++k) fs::remove(all[k]);
}

std::string file_crc32(const fs::path& path) {
  try {
    return fmt::format("{:08x}", crc32_of(read_bytes(path)));
  } catch (const CheckpointError&) {
    throw OutputFolderError(fmt::format("cannot read {} to name it in the checkpoint", path.string()));
  }
}

void sync_file(const fs::path& path) { fsync_path(path, O_RDONLY); }

}  // namespace heliostand::checkpoint
