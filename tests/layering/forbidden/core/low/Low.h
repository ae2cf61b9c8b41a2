#pragma once
// Forbidden: low includes a module above it; scripts/check-layering.cmake must fail on this line.
#include "core/high/High.h"
