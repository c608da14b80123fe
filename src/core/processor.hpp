#pragma once
// The processor a benchmark or a run ran on. Timings are only comparable on one machine, and these machines' lscpu
// "Model name" is often only "AMD EPYC": two of them with that name ran the same hectare in 524 and 829 s
// (docs/performance.md). The CPU family and model tell such machines apart, and the vector extensions say what
// PoCL can compile the kernels for (of the two earlier EPYCs, the one with AVX-512 took 688-739 s, the one without
// 829-1 024 s).
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace heliostand {

struct Processor {
  std::string model_name;                      // /proc/cpuinfo "model name"; empty where the kernel gives none
  std::optional<int> family;                   // "cpu family" (x86)
  std::optional<int> model;                    // "model" (x86)
  std::vector<std::string> vector_extensions;  // of sse4_2, avx, avx2, fma, avx512f, asimd, sve: those it has
};

// The first processor described in a /proc/cpuinfo text (the machines' cores are alike). Lines it does not know are
// skipped; a field it cannot read stays empty: a benchmark never fails for want of a description.
Processor processor_from_cpuinfo(std::istream& cpuinfo);

// This machine's processor (/proc/cpuinfo; an empty description where that cannot be read).
Processor this_processor();

// {"model_name": "...", "cpu_family": 26, "model": 2, "vector_extensions": ["avx2", ...]}, null for what is unknown.
nlohmann::ordered_json processor_json(const Processor& processor);

}  // namespace heliostand
