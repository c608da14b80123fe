#include "io/pvd_collection.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace heliostand {
namespace {

std::string xml_attribute_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

void PvdCollection::add(double timestep, std::string file) {
  auto same = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.timestep == timestep; });
  if (same != entries_.end()) {
    same->file = std::move(file);
    return;
  }
  auto after = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.timestep > timestep; });
  entries_.insert(after, Entry{timestep, std::move(file)});
}

std::string PvdCollection::to_xml() const {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const Entry& e : entries_) {
    xml += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", e.timestep,
                       xml_attribute_escape(e.file));
  }
  xml += "  </Collection>\n</VTKFile>\n";
  return xml;
}

}  // namespace heliostand
