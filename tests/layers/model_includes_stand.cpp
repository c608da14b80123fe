// Must NOT compile (CTest layers.model_cannot_include_the_stand): compiled as a source of the light module, whose
// include folder (build/layers/light) holds only the light and the layers below it.
#include "stand/stand.hpp"
