#pragma once
// Turning the stand into what an output year writes (records/stand_snapshot.hpp), and into what every year's
// stand_table.csv rows measure (records/stand_table_ledger.hpp).
#include "core/checkpoint_access.hpp"
#include "records/stand_snapshot.hpp"
#include "records/stand_table_ledger.hpp"
#include "stand/stand.hpp"

namespace heliostand {

TreeSnapshot snapshot_of(const StandTree& tree);

// The living trees of the stand now (a year without a snapshot; an output year measures its snapshot instead).
StandInventory take_inventory(const Stand& stand, int year_index);

// Remembers which trees were already written as removed or dead: an output year holds every living tree
// plus the trees that left the stand since the previous output year (shown once with their status).
class SnapshotTracker {
 public:
  // `mesh_trunks`: build each standing tree's trunk surface (only the VTK output reads it).
  explicit SnapshotTracker(bool mesh_trunks = true) : mesh_trunks_(mesh_trunks) {}
  StandSnapshot take(const Stand& stand, int year_index);
  // Whether tree `index` (Stand::trees() order) has been written as removed or dead: no later year writes it again.
  bool written_as_gone(std::size_t index) const { return index < written_as_gone_.size() && written_as_gone_[index]; }

 private:
  friend struct checkpoint::Access;
  bool mesh_trunks_;
  std::vector<bool> written_as_gone_;
};

}  // namespace heliostand
