#pragma once
// How this process's memory is given its pages. On some virtual machines the first write to a fresh 4 KiB page costs
// ten times what a huge page's does, so one binary's run moves by a tenth with glibc's allocator settings alone
// (docs/performance.md "Huge pages for malloc, where a fresh 4 KiB page is dear"). A benchmark records them beside
// the processor, so that figures taken with and without them are not compared unawares.
#include <iosfwd>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace heliostand {

struct PageSettings {
  std::optional<std::string> glibc_tunables;          // the GLIBC_TUNABLES environment variable, where set
  std::optional<std::string> transparent_huge_pages;  // the kernel's mode: "always", "madvise" or "never"
};

// The mode a /sys/kernel/mm/transparent_hugepage/enabled text chooses: its bracketed word ("always [madvise] never"
// gives "madvise"); nothing where no word is bracketed.
std::optional<std::string> chosen_transparent_huge_pages(std::istream& enabled);

// This process's settings (its environment and the running kernel's mode; what cannot be read stays empty).
PageSettings this_process_page_settings();

// {"glibc_tunables": "glibc.malloc.hugetlb=1", "transparent_huge_pages": "madvise"}, null for what is unset.
nlohmann::ordered_json page_settings_json(const PageSettings& settings);

}  // namespace heliostand
