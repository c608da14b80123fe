// The processor a benchmark records: read from /proc/cpuinfo's first block, whatever the architecture writes there.
#include "core/processor.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace heliostand {
namespace {

Processor parsed(const std::string& text) {
  std::istringstream cpuinfo(text);
  return processor_from_cpuinfo(cpuinfo);
}

// Two cores of a 2-core EPYC (abridged): the first block is read, the second not.
const std::string two_epyc_cores =
    "processor\t: 0\nvendor_id\t: AuthenticAMD\ncpu family\t: 26\nmodel\t\t: 2\nmodel name\t: AMD EPYC\n"
    "flags\t\t: fpu sse4_2 avx avx2 fma avx512f avx512dq\n\n"
    "processor\t: 1\nvendor_id\t: AuthenticAMD\ncpu family\t: 25\nmodel\t\t: 1\nmodel name\t: Other\n"
    "flags\t\t: fpu\n\n";

TEST(Processor, ReadsTheFirstX86Block) {
  const Processor processor = parsed(two_epyc_cores);
  EXPECT_EQ(processor.model_name, "AMD EPYC");
  EXPECT_EQ(processor.family, 26);
  EXPECT_EQ(processor.model, 2);
  EXPECT_EQ(processor.vector_extensions, (std::vector<std::string>{"sse4_2", "avx", "avx2", "fma", "avx512f"}));
}

TEST(Processor, TellsAMachineWithoutAvx512Apart) {
  const Processor processor =
      parsed("cpu family\t: 25\nmodel\t\t: 1\nmodel name\t: AMD EPYC\nflags\t\t: sse4_2 avx avx2 fma\n");
  EXPECT_EQ(processor.family, 25);
  EXPECT_EQ(processor.vector_extensions, (std::vector<std::string>{"sse4_2", "avx", "avx2", "fma"}));
}

TEST(Processor, FlagsAreWholeWords) {
  // An AMD Bulldozer has AMD's four-operand fma4, not fma.
  EXPECT_EQ(parsed("flags\t\t: sse4_2 avx fma4 xop\n").vector_extensions, (std::vector<std::string>{"sse4_2", "avx"}));
}

TEST(Processor, ArmFeaturesWithoutFamilyOrModelName) {
  const Processor processor = parsed("processor\t: 0\nBogoMIPS\t: 50.00\nFeatures\t: fp asimd sve atomics\n"
                                     "CPU implementer\t: 0x41\n\nprocessor\t: 1\nmodel name\t: not this one\n");
  EXPECT_EQ(processor.model_name, "");
  EXPECT_EQ(processor.family, std::nullopt);
  EXPECT_EQ(processor.model, std::nullopt);
  EXPECT_EQ(processor.vector_extensions, (std::vector<std::string>{"asimd", "sve"}));
}

TEST(Processor, UnreadableFieldsStayUnknown) {
  const Processor processor = parsed("\n\ncpu family\t: twenty-six\nmodel\t: 2x\nno colon here\nmodel name:\n");
  EXPECT_EQ(processor.family, std::nullopt);
  EXPECT_EQ(processor.model, std::nullopt);
  EXPECT_EQ(processor.model_name, "");
  EXPECT_TRUE(parsed("").vector_extensions.empty());
}

TEST(Processor, JsonNamesWhatIsKnownAndNullsTheRest) {
  const auto known = processor_json(parsed(two_epyc_cores));
  EXPECT_EQ(known.at("model_name"), "AMD EPYC");
  EXPECT_EQ(known.at("cpu_family"), 26);
  EXPECT_EQ(known.at("model"), 2);
  EXPECT_EQ(known.at("vector_extensions").size(), 5u);
  const auto unknown = processor_json(Processor{});
  EXPECT_TRUE(unknown.at("model_name").is_null());
  EXPECT_TRUE(unknown.at("cpu_family").is_null());
  EXPECT_TRUE(unknown.at("model").is_null());
  EXPECT_TRUE(unknown.at("vector_extensions").empty());
  // written out and read back, a name with quotes and a backslash stays itself
  const auto quoted = nlohmann::json::parse(processor_json(Processor{"a \"quoted\\\" name", 1, 2, {}}).dump());
  EXPECT_EQ(quoted.at("model_name"), "a \"quoted\\\" name");
}

TEST(Processor, ThisMachineIsDescribed) {
  // Linux always has /proc/cpuinfo, and every architecture heliostand is built on lists its vector extensions.
  EXPECT_FALSE(this_processor().vector_extensions.empty());
}

}  // namespace
}  // namespace heliostand
