#pragma once
// Allowed: high builds on low.
#include "core/low/Low.h"
