// SPDX-License-Identifier: GPL-3.0-or-later
// Test fixture for include_directions_catch_upward (see ../model/low.h).
#pragma once
