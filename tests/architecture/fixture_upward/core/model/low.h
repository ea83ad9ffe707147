// SPDX-License-Identifier: GPL-3.0-or-later
// Test fixture: a model header that includes a design header, against the layering rule. The
// include-direction check must fail on this tree (test include_directions_catch_upward).
#pragma once
#include "core/design/high.h"
