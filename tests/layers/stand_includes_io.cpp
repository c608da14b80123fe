// Must NOT compile (CTest layers.stand_cannot_include_io): the stand hands its records to the writers through
// records/year_recorder.hpp and never sees io/.
#include "io/stand_output.hpp"
