// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

namespace xyt::ui {

/// @p v with @p digits significant digits, as the plots' labels and the views' readouts write
/// numbers ("0.00685", "1.2e+03").
inline QString significant(double v, int digits) {
    return QString::number(v, 'g', digits);
}

} // namespace xyt::ui
