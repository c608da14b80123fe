// The kernels' floor and ceil (cl/rounding.clh): the processor's rounding instruction where the compiler offers it
// (PoCL), the OpenCL built-ins elsewhere (a GPU's own compiler). Both are exact, so the light and the root-contact
// field must come out the same, bit for bit, whichever the kernels were built with; and on PoCL the instruction is
// the one taken (else this comparison would compare a build with itself).
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "compute/kernel_files_override.hpp"
#include "compute/kernel_sources.hpp"
#include "compute/opencl_context.hpp"
#include "compute/opencl_test_backend.hpp"
#include "light/celestial_sphere.hpp"
#include "light/light_test_stands.hpp"
#include "light/opencl_light_solver.hpp"
#include "roots/grown_root_stand.hpp"
#include "roots/make_root_field_solver.hpp"

namespace heliostand::compute {
namespace {

// cl/rounding.clh as the kernels read it, with HELIOSTAND_LIBRARY_ROUNDING defined first.
std::string library_rounding_header() {
  return "#define HELIOSTAND_LIBRARY_ROUNDING\n" + kernel_source("rounding.clh");
}

// ROUNDING_BY_INSTRUCTION as cl/rounding.clh sets it on this device (as a build with HELIOSTAND_KERNEL_DIR set
// would read it).
int rounding_by_instruction(const OpenCLContext& device) {
  const std::string source = kernel_source("rounding.clh") +
                             "kernel void path(global int* out) { out[0] = ROUNDING_BY_INSTRUCTION; }\n";
  cl::Program program = build_program(device, source, "");
  cl::Buffer out(device.context, CL_MEM_WRITE_ONLY, sizeof(int));
  cl::Kernel kernel(program, "path");
  kernel.setArg(0, out);
  device.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(1), cl::NullRange);
  int by_instruction = -1;
  device.queue.enqueueReadBuffer(out, CL_TRUE, 0, sizeof by_instruction, &by_instruction);
  return by_instruction;
}

// Every kernel that rounds: the leaf balls' patch windows (light_culled, light_culled_and_alone), the far field's
// sweep and its lookups (far_field_layer, light.cl's far_field_attenuate) on a torus and on an open plot, and the
// root-contact field's grid cells and soil lookups.
struct Answers {
  std::vector<LightSample> stand, one_pass_stand, one_pass_alone;
  std::vector<roots::RootFieldSample> roots;
};

Answers answers(const ComputeBackend& backend, const OpenCLContext& cpu) {
  Answers out;
  LightParameters p;  // the default solve: culled, with its far field
  p.plot_x_max = p.plot_y_max = 8.0;
  p.cutoff_m = 1.5;
  p.transmittance = 0.6;
  p.periodic = true;
  const CelestialSphere sky(p);
  out.stand = OpenCLLightSolver(p, cpu).solve(testing::random_stand(220, 8.0, 0.15, 0.45, 5, sky, true));
  p.periodic = false;
  LightParameters alone = p;
  alone.exact = true;
  const auto balls = testing::random_stand(200, 8.0, 0.15, 0.45, 8, sky, false);
  std::vector<std::size_t> group_start;
  for (std::size_t start = 0; start <= balls.size(); start += 20) group_start.push_back(start);
  const auto both = OpenCLLightSolver(p, cpu).solve_with_each_alone(balls, group_start, OpenCLLightSolver(alone, cpu));
  if (both) out.one_pass_stand = both->stand, out.one_pass_alone = both->alone;
  roots::test_stands::GrownStand grown = roots::test_stands::grown_stand(6, 3);
  const auto queries = roots::test_stands::apices_at_every_segment_end(grown, 3);
  out.roots = roots::make_root_field_solver(backend)->solve(queries.input(grown.soil));
  return out;
}

void expect_same_bits(const std::vector<LightSample>& instruction, const std::vector<LightSample>& library,
                      const char* label) {
  ASSERT_EQ(instruction.size(), library.size()) << label;
  for (std::size_t k = 0; k < instruction.size(); ++k) {
    EXPECT_EQ(instruction[k].light, library[k].light) << label << ", ball " << k;
    EXPECT_EQ(instruction[k].vector, library[k].vector) << label << ", ball " << k;
  }
}

TEST(KernelRounding, TheInstructionAndTheLibraryGiveTheSameLightAndRootFieldBitForBit) {
  const auto backend = opencl_backend_for_test();
  if (!backend) GTEST_SKIP() << "no OpenCL device";
  OpenCLContext cpu = *backend->opencl();
  cpu.type = CL_DEVICE_TYPE_CPU;  // the one pass runs on a CPU device only; the kernel is the same on every device
  if (cpu.description.find("Portable Computing Language") != std::string::npos)
    EXPECT_EQ(rounding_by_instruction(cpu), 1) << "PoCL's clang offers the elementwise builtins: " << cpu.description;
  const Answers instruction = answers(*backend, cpu);
  Answers library;
  {
    // every kernel built in this scope takes the OpenCL built-ins' branch, as a compiler without the builtins would
    const testing::KernelFilesOverride library_rounding("library_rounding",
                                                        {{"rounding.clh", library_rounding_header()}});
    EXPECT_EQ(rounding_by_instruction(cpu), 0);
    library = answers(*backend, cpu);
  }
  ASSERT_FALSE(instruction.one_pass_stand.empty()) << "the one pass declined the open stand";
  expect_same_bits(instruction.stand, library.stand, "stand on a torus");
  expect_same_bits(instruction.one_pass_stand, library.one_pass_stand, "one pass, the stand");
  expect_same_bits(instruction.one_pass_alone, library.one_pass_alone, "one pass, each tree alone");
  ASSERT_EQ(instruction.roots.size(), library.roots.size());
  ASSERT_GT(instruction.roots.size(), 100u);
  for (std::size_t t = 0; t < instruction.roots.size(); ++t) {
    EXPECT_EQ(instruction.roots[t].contacts, library.roots[t].contacts) << "apex " << t;
    EXPECT_EQ(instruction.roots[t].contact_avoidance, library.roots[t].contact_avoidance) << "apex " << t;
    EXPECT_EQ(instruction.roots[t].moisture_pull, library.roots[t].moisture_pull) << "apex " << t;
  }
}

}  // namespace
}  // namespace heliostand::compute
