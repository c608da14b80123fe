// Must compile (CTest layers.model_includes_a_lower_layer): the control of model_includes_stand.cpp, compiled the
// same way, so that its failure is the upward include's and not a broken set-up.
#include "geometry/angles.hpp"
#include "light/light_solver.hpp"
