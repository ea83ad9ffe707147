// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/files/session_format_migration.h"

#include "ui/files/session_file.h"

#include <QJsonArray>

namespace xyt::files {

namespace {

/// @p object with the keys @p keys of @p defaults that it lacks.
QJsonObject withDefaults(QJsonObject object, const QJsonObject& defaults, const QStringList& keys) {
    for (const QString& key : keys)
        if (!object.contains(key))
            object.insert(key, defaults.value(key));
    return object;
}

/// A version-1 trajectory with its "gcode" object (the default one) unless its kind is
/// G-code: such a trajectory without its program was refused by version 1 too.
QJsonValue trajectoryFromVersion1(const QJsonValue& trajectory, const QJsonObject& defaults) {
    if (!trajectory.isObject())
        return trajectory;
    QJsonObject t = trajectory.toObject();
    if (!t.contains("gcode") && t.value("kind") != QJsonValue("gcode"))
        t.insert("gcode", defaults.value("gcode"));
    return t;
}

QJsonObject fromVersion1(QJsonObject root) {
    const QJsonObject defaults = sessionToJson(Session{});
    const QJsonObject implementation = defaults.value("implementation").toObject();
    if (!root.contains("implementation"))
        root.insert("implementation", implementation);
    else if (root.value("implementation").isObject())
        root.insert("implementation", withDefaults(root.value("implementation").toObject(),
                                                   implementation, implementation.keys()));
    if (root.value("specification").isObject())
        root.insert("specification", withDefaults(root.value("specification").toObject(),
                                                  defaults.value("specification").toObject(),
                                                  {"in_position_window_mm", "max_settle_time",
                                                   "min_phase_margin", "min_gain_margin"}));
    const QJsonObject trajectoryDefaults = defaults.value("trajectory").toObject();
    if (root.contains("trajectory"))
        root.insert("trajectory",
                    trajectoryFromVersion1(root.value("trajectory"), trajectoryDefaults));
    if (root.value("snapshots").isArray()) {
        QJsonArray snapshots = root.value("snapshots").toArray();
        for (qsizetype i = 0; i < snapshots.size(); ++i) {
            if (!snapshots[i].isObject())
                continue;
            QJsonObject snapshot = snapshots[i].toObject();
            if (snapshot.contains("trajectory"))
                snapshot.insert("trajectory", trajectoryFromVersion1(snapshot.value("trajectory"),
                                                                     trajectoryDefaults));
            snapshots[i] = snapshot;
        }
        root.insert("snapshots", snapshots);
    }
    root.insert("version", 2);
    return root;
}

} // namespace

QJsonObject migrateSessionJson(QJsonObject root, int version) {
    if (version <= 1)
        root = fromVersion1(std::move(root));
    return root;
}

} // namespace xyt::files
