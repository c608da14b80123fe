#pragma once
// The ParaView time-series index (VTK "Collection" XML, .pvd): one DataSet entry per output year with
// timestep = stand age, pointing at that year's .vtm file (path relative to the .pvd).
#include <string>
#include <vector>

namespace heliostand {

class PvdCollection {
 public:
  struct Entry {
    double timestep = 0;   // stand age, years
    std::string file;      // relative to the .pvd, '/'-separated
  };

  // Adds an entry, replacing one with the same timestep; entries stay sorted by timestep.
  void add(double timestep, std::string file);
  const std::vector<Entry>& entries() const { return entries_; }

  std::string to_xml() const;

 private:
  std::vector<Entry> entries_;
};

}  // namespace heliostand
