#pragma once
// Turning the stand into what an output year writes (io/stand_snapshot.hpp).
#include "io/stand_snapshot.hpp"
#include "stand/stand.hpp"

namespace heliostand {

TreeSnapshot snapshot_of(const StandTree& tree);

// Remembers which trees were already written as removed or dead: an output year holds every living tree
// plus the trees that left the stand since the previous output year (shown once with their status).
class SnapshotTracker {
 public:
  StandSnapshot take(const Stand& stand, int year_index);

 private:
  std::vector<bool> written_as_gone_;
};

}  // namespace heliostand
