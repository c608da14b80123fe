#pragma once
// The one door through which a checkpoint reads and restores the private state of the types that carry a run
// from one simulated year to the next (io/checkpoint_state.cpp). Each such type declares
//   friend struct checkpoint::Access;
// so that the serialization stays in io/ and the types keep their invariants closed to everyone else.
namespace heliostand::checkpoint {
struct Access;
}  // namespace heliostand::checkpoint
