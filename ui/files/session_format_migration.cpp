// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/files/session_format_migration.h"

#include "ui/files/session_file.h"

#include <QJsonArray>

#include <functional>

namespace xyt::files {

namespace {

/// @p object with the keys @p keys of @p defaults that it lacks.
QJsonObject withDefaults(QJsonObject object, const QJsonObject& defaults, const QStringList& keys) {
    for (const QString& key : keys)
        if (!object.contains(key))
            object.insert(key, defaults.value(key));
    return object;
}

/// @p root with @p change applied to each snapshot object of its "snapshots" array.
QJsonObject withEachSnapshot(QJsonObject root,
                             const std::function<void(QJsonObject& snapshot)>& change) {
    if (!root.value("snapshots").isArray())
        return root;
    QJsonArray snapshots = root.value("snapshots").toArray();
    for (qsizetype i = 0; i < snapshots.size(); ++i) {
        if (!snapshots[i].isObject())
            continue;
        QJsonObject snapshot = snapshots[i].toObject();
        change(snapshot);
        snapshots[i] = snapshot;
    }
    root.insert("snapshots", snapshots);
    return root;
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
    root = withEachSnapshot(std::move(root), [&](QJsonObject& snapshot) {
        if (snapshot.contains("trajectory"))
            snapshot.insert("trajectory", trajectoryFromVersion1(snapshot.value("trajectory"),
                                                                 trajectoryDefaults));
    });
    root.insert("version", 2);
    return root;
}

/// @p axes (an array of axis objects) with an empty "parameters" object in each axis.
QJsonValue axesWithParameters(const QJsonValue& axes) {
    if (!axes.isArray())
        return axes;
    QJsonArray out = axes.toArray();
    for (qsizetype i = 0; i < out.size(); ++i) {
        if (!out[i].isObject())
            continue;
        QJsonObject axis = out[i].toObject();
        if (!axis.contains("parameters"))
            axis.insert("parameters", QJsonObject{});
        out[i] = axis;
    }
    return out;
}

/// Version 2 had no registered methods, so no axis has parameters.
QJsonObject fromVersion2(QJsonObject root) {
    if (root.contains("axes"))
        root.insert("axes", axesWithParameters(root.value("axes")));
    root = withEachSnapshot(std::move(root), [](QJsonObject& snapshot) {
        if (snapshot.contains("axes"))
            snapshot.insert("axes", axesWithParameters(snapshot.value("axes")));
    });
    root.insert("version", 3);
    return root;
}

/// @p trajectory with the cubic profile in its "cubic" object, where it has none.
void withCubicProfile(QJsonObject& trajectory) {
    if (!trajectory.value("cubic").isObject())
        return;
    QJsonObject cubic = trajectory.value("cubic").toObject();
    if (!cubic.contains("profile"))
        cubic.insert("profile", QStringLiteral("cubic"));
    trajectory.insert("cubic", cubic);
}

/// Version 3's point-to-point move was always Braga et al.'s cubic.
QJsonObject fromVersion3(QJsonObject root) {
    const auto migrate = [](QJsonObject& holder) {
        if (!holder.value("trajectory").isObject())
            return;
        QJsonObject trajectory = holder.value("trajectory").toObject();
        withCubicProfile(trajectory);
        holder.insert("trajectory", trajectory);
    };
    migrate(root);
    root = withEachSnapshot(std::move(root), migrate);
    root.insert("version", 4);
    return root;
}

} // namespace

QJsonObject migrateSessionJson(QJsonObject root, int version) {
    if (version <= 1)
        root = fromVersion1(std::move(root));
    if (version <= 2)
        root = fromVersion2(std::move(root));
    if (version <= 3)
        root = fromVersion3(std::move(root));
    // Version 5 only adds the optional "friction" object of an axis, version 6 the optional
    // "cross_coupling" object and version 7 the optional "flexible_mode" and "notch" of an
    // axis' "gt": nothing to fill in.
    root.insert("version", kSessionFormatVersion);
    return root;
}

} // namespace xyt::files
