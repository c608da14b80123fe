#pragma once
// The four root types of seed 003 (Ohshida, Muraoka, Chiba) and its branching rules
//   main → main, lateral;  lateral → lateral, sinker, branch;  sinker → sinker, branch;  branch → branch.
// "May branch into" — each allowed child type has its own branching frequency (root_parameters.hpp).
#include <array>
#include <string_view>

namespace heliostand::roots {

enum class RootType : int { main = 0, lateral = 1, sinker = 2, fine = 3 };  // fine = 枝根, fine branch root

inline constexpr int root_type_count = 4;
inline constexpr std::array<RootType, root_type_count> all_root_types = {RootType::main, RootType::lateral,
                                                                         RootType::sinker, RootType::fine};

constexpr int index_of(RootType type) { return static_cast<int>(type); }

constexpr std::string_view name_of(RootType type) {
  switch (type) {
    case RootType::main: return "main";
    case RootType::lateral: return "lateral";
    case RootType::sinker: return "sinker";
    case RootType::fine: return "fine";
  }
  return "?";
}

// The seed's production rules P: may a root of type `parent` start a new root of type `child`?
constexpr bool may_branch_into(RootType parent, RootType child) {
  switch (parent) {
    case RootType::main: return child == RootType::main || child == RootType::lateral;
    case RootType::lateral: return child != RootType::main;
    case RootType::sinker: return child == RootType::sinker || child == RootType::fine;
    case RootType::fine: return child == RootType::fine;
  }
  return false;
}

}  // namespace heliostand::roots
