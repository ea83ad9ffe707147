// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: the session file loader (ui/files/session_file.h sessionFromBytes) on
// arbitrary bytes, as a hand-edited or truncated file holds them. It must never crash; a session it
// accepts must hold finite numbers and survive a save/load round trip unchanged, and its labels
// must reach the exports only as text that cannot end a comment or drive a terminal.
#include "tests/fuzz/fuzz_support.h"

#include "core/io/text_escape.h"
#include "ui/files/session_file.h"

#include <QByteArray>
#include <QJsonDocument>

#include <cstdint>

namespace {

void requireFinite(const xyt::AxisSettings& axis) {
    XYT_FUZZ_REQUIRE_FINITE(axis.gt.plant.k0);
    XYT_FUZZ_REQUIRE_FINITE(axis.gt.plant.a1);
    XYT_FUZZ_REQUIRE_FINITE(axis.gt.plant.a2);
    XYT_FUZZ_REQUIRE_FINITE(axis.gt.omegaNRadPerSec);
    XYT_FUZZ_REQUIRE_FINITE(axis.gt.kp);
    XYT_FUZZ_REQUIRE_FINITE(axis.gt.modelUnitsPerPositionUnit);
    XYT_FUZZ_REQUIRE_FINITE(axis.pp.a);
    XYT_FUZZ_REQUIRE_FINITE(axis.pp.b);
    XYT_FUZZ_REQUIRE_FINITE(axis.pp.t1);
    XYT_FUZZ_REQUIRE_FINITE(axis.pp.tsSeconds);
}

/// What the exports make of a label: one comment line that no comment syntax can end early,
/// and terminal text of printable characters.
void requireInertLabel(const std::string& label) {
    const std::string c = xyt::commentText(label, xyt::CommentSyntax::C);
    XYT_FUZZ_REQUIRE(c.find("*/") == std::string::npos && c.find("/*") == std::string::npos &&
                     c.find("??") == std::string::npos);
    for (const std::string& text :
         {c, xyt::commentText(label, xyt::CommentSyntax::Octave), xyt::terminalText(label)})
        for (const char ch : text)
            XYT_FUZZ_REQUIRE(static_cast<unsigned char>(ch) >= 0x20 && ch != 0x7f);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const xyt::files::SessionLoadResult loaded = xyt::files::sessionFromBytes(bytes);
    if (!loaded.ok) {
        XYT_FUZZ_REQUIRE(!loaded.message().isEmpty());
        return 0;
    }
    const xyt::Session& s = loaded.session;
    for (const auto& axis : s.axes) {
        requireFinite(axis);
        requireInertLabel(axis.label);
    }
    XYT_FUZZ_REQUIRE_FINITE(s.umaxVolts);
    XYT_FUZZ_REQUIRE_FINITE(s.controllerTsSeconds);
    XYT_FUZZ_REQUIRE_FINITE(s.trajectory.effectiveDurationSeconds());
    XYT_FUZZ_REQUIRE_FINITE(s.trajectory.dtSeconds);
    // The digital implementation: within the ranges the sampled-data loop accepts.
    XYT_FUZZ_REQUIRE_FINITE(s.implementation.encoderResolutionMm);
    XYT_FUZZ_REQUIRE_FINITE(s.implementation.trackingTimeSeconds);
    XYT_FUZZ_REQUIRE(s.implementation.encoderResolutionMm >= 0.0 &&
                     s.implementation.trackingTimeSeconds >= 0.0);
    XYT_FUZZ_REQUIRE(s.implementation.delaySamples >= 0 && s.implementation.delaySamples <= 100);
    XYT_FUZZ_REQUIRE(s.implementation.dacBits >= 0 && s.implementation.dacBits <= 32);
    for (const auto& snapshot : s.snapshots)
        for (const auto& axis : snapshot.axes)
            requireFinite(axis);

    // What the workbench saves from an accepted session must load back to the same session.
    const QByteArray saved = QJsonDocument(xyt::files::sessionToJson(s)).toJson();
    const xyt::files::SessionLoadResult reloaded = xyt::files::sessionFromBytes(saved);
    XYT_FUZZ_REQUIRE(reloaded.ok);
    XYT_FUZZ_REQUIRE(reloaded.session == s);
    return 0;
}
