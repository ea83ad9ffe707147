// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/help/welcome_dialog.h"

#include "ui/help/user_guide_window.h"
#include "ui/session/session_file_controller.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

namespace xyt::ui {

bool WelcomeDialog::shouldShowAtStart() {
    const QSettings settings;
    return !settings.contains(kShownKey) || settings.value(kAtStartKey, false).toBool();
}

QList<ExampleSession> WelcomeDialog::exampleSessions(const QString& folder) {
    QList<ExampleSession> found;
    if (folder.isEmpty())
        return found;
    const QDir dir(folder);
    QFile list(dir.filePath("sessions.json"));
    if (list.open(QIODevice::ReadOnly)) {
        const QJsonDocument doc = QJsonDocument::fromJson(list.read(1 << 20));
        for (const QJsonValue& value : doc.array()) {
            const QJsonObject entry = value.toObject();
            ExampleSession example{entry.value("file").toString(), entry.value("title").toString(),
                                   entry.value("tutorial").toString()};
            // Only a file of the folder itself: a list is data, not a path to follow.
            if (example.file.isEmpty() || QFileInfo(example.file).fileName() != example.file ||
                !QFileInfo(dir.filePath(example.file)).isFile())
                continue;
            if (example.title.isEmpty())
                example.title = example.file;
            found.append(example);
        }
        if (doc.isArray())
            return found;
    }
    // No list (or not an array): every session file of the folder by its name.
    for (const QString& name : dir.entryList({"*.json"}, QDir::Files, QDir::Name))
        if (name != "sessions.json")
            found.append({name, name, QString()});
    return found;
}

QUrl WelcomeDialog::tutorialPage(const QString& tutorial) {
    QString path = tutorial.trimmed();
    if (path.isEmpty())
        return QUrl();
    if (path.startsWith("docs/"))
        path = path.mid(QStringLiteral("docs/").size());
    if (path.startsWith("user-guide/"))
        path = path.mid(QStringLiteral("user-guide/").size());
    if (!path.endsWith(".md"))
        path += ".md";
    return UserGuideWindow::docsUrl("user-guide/" + path);
}

WelcomeDialog::WelcomeDialog(SessionFileController* files, const QString& examplesFolder,
                             QWidget* parent)
    : QDialog(parent), files_(files), folder_(examplesFolder),
      examples_(exampleSessions(examplesFolder)) {
    setObjectName("welcomeDialog");
    setWindowTitle(tr("Welcome to XY Tune"));
    resize(760, 480);

    auto* intro = new QLabel(
        tr("XY Tune tunes the position controllers of two-axis XY tables. Start with a tutorial "
           "(it opens in the user guide, F1) or open an example session in the workbench."),
        this);
    intro->setWordWrap(true);

    // The tutorials: the user guide's pages (its index first, as "the whole guide").
    auto* tutorialBox = new QGroupBox(tr("Tutorials"), this);
    tutorials_ = new QListWidget(tutorialBox);
    tutorials_->setObjectName("welcomeTutorials");
    tutorials_->setToolTip(tr("The user guide's tutorials: double-click one to read it in the "
                              "user guide window"));
    for (const QUrl& page : UserGuideWindow::pages()) {
        if (!page.path().startsWith("/docs/user-guide/"))
            continue;
        const bool index = page.path() == "/docs/user-guide/index.md";
        auto* item = new QListWidgetItem(
            index ? tr("The user guide: contents") : UserGuideWindow::pageTitle(page), tutorials_);
        item->setData(Qt::UserRole, page);
    }
    if (tutorials_->count() == 0) { // a build without the guide: its reference pages
        auto* item = new QListWidgetItem(tr("The user guide (reference pages)"), tutorials_);
        item->setData(Qt::UserRole, UserGuideWindow::homePage());
    }
    auto* readTutorial = new QPushButton(tr("Read"), tutorialBox);
    readTutorial->setToolTip(tr("Open the selected tutorial in the user guide"));
    auto* tutorialLayout = new QVBoxLayout(tutorialBox);
    tutorialLayout->addWidget(tutorials_);
    tutorialLayout->addWidget(readTutorial, 0, Qt::AlignRight);

    // The example sessions.
    auto* sessionBox = new QGroupBox(tr("Example sessions"), this);
    sessions_ = new QListWidget(sessionBox);
    sessions_->setObjectName("welcomeSessions");
    sessions_->setWordWrap(true);
    sessions_->setToolTip(tr("Example sessions shipped with XY Tune: double-click one to open "
                             "it in the workbench (as File › Open would)"));
    for (const ExampleSession& example : examples_) {
        auto* item = new QListWidgetItem(example.title == example.file
                                             ? example.file
                                             : tr("%1 (%2)").arg(example.title, example.file),
                                         sessions_);
        item->setToolTip(QDir(folder_).filePath(example.file));
    }
    if (examples_.isEmpty()) {
        auto* none =
            new QListWidgetItem(tr("No example sessions were found in %1")
                                    .arg(folder_.isEmpty() ? tr("(no examples folder)") : folder_),
                                sessions_);
        none->setFlags(Qt::NoItemFlags);
    }
    openSession_ = new QPushButton(tr("Open session"), sessionBox);
    openSession_->setToolTip(tr("Open the selected example in the workbench"));
    sessionTutorial_ = new QPushButton(tr("Its tutorial"), sessionBox);
    sessionTutorial_->setToolTip(tr("Read the tutorial that walks through the selected example"));
    openSession_->setEnabled(false);
    sessionTutorial_->setEnabled(false);
    auto* sessionButtons = new QHBoxLayout;
    sessionButtons->addStretch(1);
    sessionButtons->addWidget(sessionTutorial_);
    sessionButtons->addWidget(openSession_);
    auto* sessionLayout = new QVBoxLayout(sessionBox);
    sessionLayout->addWidget(sessions_);
    sessionLayout->addLayout(sessionButtons);

    showAtStart_ = new QCheckBox(tr("Show at start"), this);
    showAtStart_->setObjectName("welcomeShowAtStart");
    showAtStart_->setToolTip(
        tr("Show this page each time XY Tune starts (it is always in Help › Tutorials)"));
    showAtStart_->setChecked(QSettings().value(kAtStartKey, false).toBool());
    auto* close = new QDialogButtonBox(QDialogButtonBox::Close, this);

    auto* lists = new QHBoxLayout;
    lists->addWidget(tutorialBox, 1);
    lists->addWidget(sessionBox, 1);
    auto* bottom = new QHBoxLayout;
    bottom->addWidget(showAtStart_);
    bottom->addStretch(1);
    bottom->addWidget(close);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(lists, 1);
    layout->addLayout(bottom);

    connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(showAtStart_, &QCheckBox::toggled, this,
            [](bool on) { QSettings().setValue(kAtStartKey, on); });
    connect(tutorials_, &QListWidget::itemActivated, this,
            [this](QListWidgetItem* item) { openTutorial(tutorials_->row(item)); });
    connect(readTutorial, &QPushButton::clicked, this,
            [this] { openTutorial(tutorials_->currentRow()); });
    connect(sessions_, &QListWidget::currentRowChanged, this, [this](int row) {
        const bool valid = row >= 0 && row < examples_.size();
        openSession_->setEnabled(valid);
        sessionTutorial_->setEnabled(valid && !examples_.at(row).tutorial.isEmpty());
    });
    connect(sessions_, &QListWidget::itemActivated, this,
            [this](QListWidgetItem* item) { openExample(sessions_->row(item)); });
    connect(openSession_, &QPushButton::clicked, this,
            [this] { openExample(sessions_->currentRow()); });
    connect(sessionTutorial_, &QPushButton::clicked, this, [this] {
        const int row = sessions_->currentRow();
        if (row >= 0 && row < examples_.size())
            emit tutorialRequested(tutorialPage(examples_.at(row).tutorial));
    });
}

bool WelcomeDialog::openExample(int index) {
    if (index < 0 || index >= examples_.size() || !files_ || !files_->maybeSave())
        return false;
    return files_->openFile(QDir(folder_).filePath(examples_.at(index).file));
}

void WelcomeDialog::openTutorial(int row) {
    if (row < 0 || row >= tutorials_->count())
        return;
    const QUrl page = tutorials_->item(row)->data(Qt::UserRole).toUrl();
    if (page.isValid())
        emit tutorialRequested(page);
}

void WelcomeDialog::showEvent(QShowEvent* event) {
    QSettings().setValue(kShownKey, true);
    QDialog::showEvent(event);
}

} // namespace xyt::ui
