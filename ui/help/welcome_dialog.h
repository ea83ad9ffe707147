// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QList>
#include <QString>
#include <QUrl>

class QCheckBox;
class QListWidget;
class QPushButton;

namespace xyt::ui {

class SessionFileController;

/// One example session offered on the first-start page.
struct ExampleSession {
    QString file;     ///< file name in the examples folder
    QString title;    ///< what the page shows (the file name when no list names it)
    QString tutorial; ///< the user-guide page that walks through it ("" for none)
};

/**
 * The first-start page (Help › Tutorials): the tutorials of the user guide, opened in the
 * UserGuideWindow (tutorialRequested), and the example sessions of the examples folder, opened
 * in the workbench through SessionFileController::openFile as File › Open would. The examples
 * are those listed in the folder's sessions.json (an array of {"file", "title", "tutorial"}), or,
 * without that list, every *.json session in the folder by its file name.
 *
 * It is shown at start when the setting kShownKey is absent (the first start) or kAtStartKey is
 * true (its "Show at start" box); the decision is main()'s, in the interactive path only, so a
 * --screenshot run and the tests never see it.
 */
class WelcomeDialog : public QDialog {
    Q_OBJECT
public:
    /// QSettings key written once the page has been shown.
    static constexpr const char* kShownKey = "ui/welcomeShown";
    /// QSettings key of the "Show at start" box (false when absent).
    static constexpr const char* kAtStartKey = "ui/welcomeAtStart";

    /// @p examplesFolder: where the example sessions and sessions.json are
    /// (examplesFolder() of ui/session/install_paths.h in the workbench).
    WelcomeDialog(SessionFileController* files, const QString& examplesFolder,
                  QWidget* parent = nullptr);

    /// Whether main() shows the page at start, from the application's QSettings.
    static bool shouldShowAtStart();
    /// The example sessions of @p folder (see the class comment), in the list's order or by file
    /// name; a listed file that does not exist is left out.
    static QList<ExampleSession> exampleSessions(const QString& folder);
    /// The user-guide page of a tutorial named in sessions.json ("ballbar", "ballbar.md",
    /// "user-guide/ballbar.md" and "docs/user-guide/ballbar.md" all name
    /// qrc:/docs/user-guide/ballbar.md).
    static QUrl tutorialPage(const QString& tutorial);

    QListWidget* tutorialList() const { return tutorials_; }
    QListWidget* sessionList() const { return sessions_; }
    QCheckBox* showAtStartBox() const { return showAtStart_; }
    const QList<ExampleSession>& examples() const { return examples_; }

    /// Opens example @p index in the workbench (asking to save unsaved work first); false when
    /// it was not opened (refused, or the user cancelled).
    bool openExample(int index);
    /// Opens the tutorial of the list's row @p row in the user guide.
    void openTutorial(int row);

signals:
    /// A user-guide page to show (a qrc URL under :/docs).
    void tutorialRequested(const QUrl& page);

protected:
    void showEvent(QShowEvent* event) override;

private:
    SessionFileController* files_;
    QString folder_;
    QList<ExampleSession> examples_;
    QListWidget* tutorials_ = nullptr;
    QListWidget* sessions_ = nullptr;
    QPushButton* openSession_ = nullptr;
    QPushButton* sessionTutorial_ = nullptr;
    QCheckBox* showAtStart_ = nullptr;
};

} // namespace xyt::ui
