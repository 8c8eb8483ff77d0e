#pragma once
// Forwarding header: the input types live in core/ (below plants), see frictionlab/core/input.hpp.
#include "frictionlab/core/input.hpp"
