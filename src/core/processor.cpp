#include "core/processor.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <fstream>
#include <istream>
#include <iterator>
#include <sstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/json_or_null.hpp"
#include "core/trim_blanks.hpp"

namespace heliostand {
namespace {

// The extensions a kernel compiler vectorises with: x86's from SSE4.2 to AVX-512, then 64-bit Arm's (its "Features").
constexpr std::array<const char*, 7> known_vector_extensions{"sse4_2", "avx", "avx2", "fma", "avx512f", "asimd", "sve"};

std::optional<int> integer(std::string_view text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::vector<std::string> vector_extensions(std::string_view flags) {
  std::vector<std::string> present;
  std::istringstream words{std::string(flags)};
  const std::vector<std::string> all{std::istream_iterator<std::string>(words), {}};
  for (const char* extension : known_vector_extensions)
    if (std::find(all.begin(), all.end(), extension) != all.end()) present.emplace_back(extension);
  return present;
}

}  // namespace

Processor processor_from_cpuinfo(std::istream& cpuinfo) {
  Processor processor;
  bool flags_seen = false;
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (trim_blanks(line).empty()) {
      if (!processor.model_name.empty() || flags_seen) break;  // the end of the first processor's block
      continue;
    }
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    const std::string_view key = trim_blanks(std::string_view(line).substr(0, colon));
    const std::string_view value = trim_blanks(std::string_view(line).substr(colon + 1));
    if (key == "model name")
      processor.model_name = std::string(value);
    else if (key == "cpu family")
      processor.family = integer(value);
    else if (key == "model")
      processor.model = integer(value);
    else if (key == "flags" || key == "Features")
      processor.vector_extensions = vector_extensions(value), flags_seen = true;
  }
  return processor;
}

Processor this_processor() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  return cpuinfo ? processor_from_cpuinfo(cpuinfo) : Processor{};
}

nlohmann::ordered_json processor_json(const Processor& processor) {
  nlohmann::ordered_json json;
  json["model_name"] =
      processor.model_name.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(processor.model_name);
  json["cpu_family"] = json_or_null(processor.family);
  json["model"] = json_or_null(processor.model);
  json["vector_extensions"] = processor.vector_extensions;
  return json;
}

}  // namespace heliostand
