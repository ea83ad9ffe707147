// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/pole_zero_map.h"

namespace xyt {

PoleZeroSet poleZeroSet(const std::string& name, const TransferFunction& tf) {
    PoleZeroSet set{name, tf.tsSeconds(), tf.poles(), tf.zeros()};
    sortRoots(set.poles);
    sortRoots(set.zeros);
    return set;
}

std::vector<PoleZeroSet> gtPoleZeroSets(const GtDesign& design) {
    return {poleZeroSet("plant", design.loopPlant), poleZeroSet("controller", design.controller),
            poleZeroSet("open loop", design.openLoop),
            poleZeroSet("closed loop", design.closedLoop),
            poleZeroSet("reference model", design.referenceModel)};
}

} // namespace xyt
