// Must compile (CTest layers.stand_includes_records): the control of stand_includes_io.cpp.
#include "records/year_recorder.hpp"
#include "stand/stand_year.hpp"
