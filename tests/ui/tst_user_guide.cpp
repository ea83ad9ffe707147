// SPDX-License-Identifier: GPL-3.0-or-later
// Help › User guide and the first-start page through their real widgets offscreen: the guide
// opens its home page from the resources, every page of docs/ is bundled, a link clicked in a
// page opens the page it names and Back returns; the first-start page lists the example sessions
// of a folder (from its sessions.json, or its files without one), opens one in the workbench,
// and keeps its "Show at start" choice in the settings.
#include "ui/files/session_file.h"
#include "ui/help/user_guide_window.h"
#include "ui/help/welcome_dialog.h"
#include "ui/main_window.h"
#include "ui/session/session_file_controller.h"
#include "ui/session/tuning_session.h"

#include <QCheckBox>
#include <QDirIterator>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QListWidget>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTextImageFormat>
#include <QToolButton>

#include <memory>

using namespace xyt;
using namespace xyt::ui;

namespace {

/// The first link of the page shown whose target is another bundled Markdown page, with the
/// position of its text in the document; an empty URL when the page holds none.
std::pair<QUrl, int> firstPageLink(QTextBrowser* browser) {
    for (QTextBlock block = browser->document()->begin(); block.isValid(); block = block.next())
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextFragment fragment = it.fragment();
            const QString href = fragment.charFormat().anchorHref();
            if (fragment.charFormat().isAnchor() && QUrl(href).isRelative() &&
                QUrl(href).path().endsWith(".md"))
                return {QUrl(href), fragment.position() + fragment.length() / 2};
        }
    return {QUrl(), -1};
}

/// Writes @p session as @p name in @p folder.
void writeSession(const Session& session, const QString& folder, const QString& name) {
    QString error;
    QVERIFY2(files::saveSessionFile(session, QDir(folder).filePath(name), &error),
             qPrintable(error));
}

void writeList(const QString& folder, const QJsonArray& entries) {
    QFile list(QDir(folder).filePath("sessions.json"));
    QVERIFY(list.open(QIODevice::WriteOnly));
    list.write(QJsonDocument(entries).toJson());
}

} // namespace

class TstUserGuide : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // the settings stay out of $HOME
        QCoreApplication::setOrganizationName("xytune-tests-user-guide");
    }
    void init() { QSettings().clear(); }

    // Every page and image of the source tree's docs/ is in the resources, at the same path.
    void everyPageIsBundled() {
        const QDir docs(QStringLiteral(XYT_SOURCE_DIR) + "/docs");
        QVERIFY(docs.exists());
        int pages = 0;
        QDirIterator it(docs.path(), {"*.md", "*.png"}, QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString relative = docs.relativeFilePath(it.next());
            if (relative.endsWith(".png") && !relative.startsWith("images/"))
                continue; // only docs/images/*.png are bundled (the pages' pictures)
            QVERIFY2(QFile::exists(":/docs/" + relative), qPrintable(relative));
            pages += relative.endsWith(".md");
        }
        // The reference pages are there at least, and pages() lists each Markdown page once.
        QVERIFY(pages >= 6);
        QCOMPARE(UserGuideWindow::pages().size(), pages);
        for (const char* page : {"cli.md", "session-format.md", "exports.md", "equations.md",
                                 "architecture.md", "contributing.md"})
            QVERIFY2(QFile::exists(QStringLiteral(":/docs/") + page), page);
    }

    // The window opens on its home page (the guide's index, else the command-line reference),
    // rendered from Markdown, with every page in the contents list.
    void opensTheHomePage() {
        UserGuideWindow guide;
        guide.show();
        QVERIFY(QTest::qWaitForWindowExposed(&guide));
        const QUrl home = UserGuideWindow::homePage();
        const bool hasIndex = QFile::exists(":/docs/user-guide/index.md");
        QCOMPARE(home, UserGuideWindow::docsUrl(hasIndex ? "user-guide/index.md" : "cli.md"));
        QCOMPARE(guide.currentPage(), home);
        // Rendered, not shown as source: the page's first heading is text without its "# ".
        const QString title = UserGuideWindow::pageTitle(home);
        QVERIFY(!title.isEmpty());
        QVERIFY(guide.browser()->toPlainText().startsWith(title));
        int listed = 0;
        for (int row = 0; row < guide.contents()->count(); ++row)
            listed += guide.contents()->item(row)->data(Qt::UserRole).isValid();
        QCOMPARE(listed, UserGuideWindow::pages().size());
        QVERIFY(!guide.backButton()->isEnabled());
    }

    // A relative link clicked in a page opens the page it names; Back and Forward go through the
    // history; a page chosen in the contents is shown.
    void followsALinkAndComesBack() {
        UserGuideWindow guide;
        guide.show();
        QVERIFY(QTest::qWaitForWindowExposed(&guide));
        guide.showPage(QStringLiteral("cli.md"));
        const QUrl from = guide.currentPage();
        QCOMPARE(from, UserGuideWindow::docsUrl("cli.md"));
        const auto [link, position] = firstPageLink(guide.browser());
        QVERIFY2(link.isValid(), "cli.md links to no other page");
        const QUrl expected = from.resolved(link).adjusted(QUrl::RemoveFragment);
        QVERIFY(QFile::exists(":" + expected.path()));
        // Click the link's text where it is drawn.
        QTextCursor cursor(guide.browser()->document());
        cursor.setPosition(position);
        guide.browser()->setTextCursor(cursor);
        guide.browser()->ensureCursorVisible();
        const QPoint at = guide.browser()->cursorRect(cursor).center();
        QTest::mouseClick(guide.browser()->viewport(), Qt::LeftButton, {}, at);
        QTRY_COMPARE(guide.currentPage(), expected);
        // The contents mark the page shown (a new page, as after Back and Forward below).
        QCOMPARE(guide.contents()->currentItem()->data(Qt::UserRole).toUrl(), expected);
        QVERIFY(guide.backButton()->isEnabled());
        QTest::mouseClick(guide.backButton(), Qt::LeftButton);
        QTRY_COMPARE(guide.currentPage(), from);
        QCOMPARE(guide.contents()->currentItem()->data(Qt::UserRole).toUrl(), from);
        QVERIFY(guide.forwardButton()->isEnabled());
        QTest::mouseClick(guide.forwardButton(), Qt::LeftButton);
        QTRY_COMPARE(guide.currentPage(), expected);
        // The contents follow the page shown, and a row chosen there shows its page.
        QCOMPARE(guide.contents()->currentItem()->data(Qt::UserRole).toUrl(), expected);
        for (int row = 0; row < guide.contents()->count(); ++row) {
            const QUrl page = guide.contents()->item(row)->data(Qt::UserRole).toUrl();
            if (page == UserGuideWindow::docsUrl("equations.md")) {
                guide.contents()->setCurrentRow(row);
                QCOMPARE(guide.currentPage(), page);
            }
        }
        QCOMPARE(guide.currentPage(), UserGuideWindow::docsUrl("equations.md"));
        QTest::mouseClick(guide.homeButton(), Qt::LeftButton);
        QCOMPARE(guide.currentPage(), UserGuideWindow::homePage());
    }

    // A link to a section (GitHub's anchor of a heading, as the pages write them) scrolls to it:
    // the command table of cli.md links to each command's section.
    void aSectionLinkScrollsToIt() {
        UserGuideWindow guide;
        guide.resize(900, 500);
        guide.show();
        QVERIFY(QTest::qWaitForWindowExposed(&guide));
        guide.showPage(QStringLiteral("cli.md"));
        QScrollBar* scroll = guide.browser()->verticalScrollBar();
        QCOMPARE(scroll->value(), 0);
        emit guide.browser()->anchorClicked(QUrl(QStringLiteral("#excite"))); // the last command
        QTRY_VERIFY(scroll->value() > 0);
        QCOMPARE(guide.currentPage(), UserGuideWindow::docsUrl("cli.md"));
        const int excite = scroll->value();
        // From another page, to a section of cli.md: the page opens at that section.
        guide.showPage(QStringLiteral("exports.md"));
        emit guide.browser()->anchorClicked(QUrl(QStringLiteral("cli.md#export")));
        QTRY_COMPARE(guide.currentPage(), UserGuideWindow::docsUrl("cli.md"));
        QTRY_VERIFY(scroll->value() > 0);
        QVERIFY(scroll->value() < excite); // export comes before excite
    }

    // Help › User guide and Help › Command-line reference open one window at the right page.
    // The screenshots (1366 px) are drawn at the width the page has, their aspect kept; never
    // wider than the page (it would scroll sideways) and never enlarged.
    void imagesFitThePage() {
        UserGuideWindow guide;
        guide.resize(800, 600);
        guide.show();
        QVERIFY(QTest::qWaitForWindowExposed(&guide));
        guide.showPage(QStringLiteral("user-guide/index.md"));
        const auto imageWidths = [&guide] {
            std::vector<std::pair<double, double>> sizes;
            QTextDocument* document = guide.browser()->document();
            for (QTextBlock block = document->begin(); block.isValid(); block = block.next())
                for (auto it = block.begin(); !it.atEnd(); ++it)
                    if (it.fragment().charFormat().isImageFormat()) {
                        const QTextImageFormat f = it.fragment().charFormat().toImageFormat();
                        sizes.emplace_back(f.width(), f.height());
                    }
            return sizes;
        };
        const auto narrow = imageWidths();
        QVERIFY(!narrow.empty()); // the index shows the window
        const int page = guide.browser()->viewport()->width();
        for (const auto& [w, h] : narrow) {
            QVERIFY2(w > 0 && w <= page,
                     qPrintable(QStringLiteral("%1 px on %2").arg(w).arg(page)));
            QVERIFY(std::abs(h / w - 768.0 / 1366.0) < 0.01); // the screenshots' 1366x768
        }
        // Wider than the picture: its own width, not enlarged.
        guide.resize(1800, 700);
        QTest::qWait(20);
        for (const auto& [w, h] : imageWidths())
            QCOMPARE(w, 1366.0);
    }

    void theHelpMenuOpensTheGuide() {
        TuningSession session;
        MainWindow window(&session);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        UserGuideWindow* guide = window.showUserGuide(UserGuideWindow::docsUrl("cli.md"));
        QVERIFY(guide->isVisible());
        QCOMPARE(guide->currentPage(), UserGuideWindow::docsUrl("cli.md"));
        QCOMPARE(window.showUserGuide(), guide); // the same window again
        QCOMPARE(window.findChildren<UserGuideWindow*>().size(), 1);
    }

    // sessions.json names the examples (a listed file that is missing is left out); opening one
    // puts that session in the workbench.
    void listsAndOpensTheListedSessions() {
        QTemporaryDir folder;
        QVERIFY(folder.isValid());
        Session first = Session::paperDefault();
        first.umaxVolts = 1.75;
        Session second = Session::paperDefault();
        second.axes[0].method = DesignMethod::PidFeedforward;
        writeSession(first, folder.path(), "slow_axes.json");
        writeSession(second, folder.path(), "pid.json");
        writeList(folder.path(),
                  {QJsonObject{{"file", "pid.json"},
                               {"title", "PID and feedforward"},
                               {"tutorial", "feedforward"}},
                   QJsonObject{{"file", "missing.json"}, {"title", "Not there"}},
                   QJsonObject{{"file", "slow_axes.json"}, {"title", "A lower limit"}}});
        TuningSession session;
        MainWindow window(&session);
        WelcomeDialog page(window.files(), folder.path(), &window);
        page.show();
        QVERIFY(QTest::qWaitForWindowExposed(&page));
        QCOMPARE(page.sessionList()->count(), 2);
        QCOMPARE(page.sessionList()->item(0)->text(),
                 QStringLiteral("PID and feedforward (pid.json)"));
        QCOMPARE(page.sessionList()->item(1)->text(),
                 QStringLiteral("A lower limit (slow_axes.json)"));
        QCOMPARE(page.examples().at(0).tutorial, QStringLiteral("feedforward"));
        for (const char* name : {"feedforward", "feedforward.md", "user-guide/feedforward.md",
                                 "docs/user-guide/feedforward.md"})
            QCOMPARE(WelcomeDialog::tutorialPage(QString::fromLatin1(name)),
                     UserGuideWindow::docsUrl("user-guide/feedforward.md"));
        QVERIFY(session.session().umaxVolts != 1.75);
        // A double-click opens the session, as File › Open would.
        QListWidget* list = page.sessionList();
        list->scrollToItem(list->item(1));
        const QPoint at = list->visualItemRect(list->item(1)).center();
        // (A press first, as a real double click has: the view activates the pressed item.)
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, at);
        QTest::mouseDClick(list->viewport(), Qt::LeftButton, {}, at);
        QCOMPARE(session.session().umaxVolts, 1.75);
        QCOMPARE(window.files()->currentFile(), QDir(folder.path()).filePath("slow_axes.json"));
        QVERIFY(page.openExample(0));
        QCOMPARE(session.session().axes[0].method, DesignMethod::PidFeedforward);
    }

    // Without sessions.json, every session file of the folder by its file name.
    void withoutAListEveryFile() {
        QTemporaryDir folder;
        writeSession(Session::paperDefault(), folder.path(), "b.json");
        writeSession(Session::paperDefault(), folder.path(), "a.json");
        QFile other(QDir(folder.path()).filePath("notes.txt"));
        QVERIFY(other.open(QIODevice::WriteOnly));
        const QList<ExampleSession> found = WelcomeDialog::exampleSessions(folder.path());
        QCOMPARE(found.size(), 2);
        QCOMPARE(found.at(0).file, QStringLiteral("a.json"));
        QCOMPARE(found.at(0).title, QStringLiteral("a.json"));
        QCOMPARE(found.at(1).file, QStringLiteral("b.json"));
    }

    // A tutorial chosen on the page asks for its user-guide page.
    void aTutorialOpensInTheGuide() {
        TuningSession session;
        MainWindow window(&session);
        WelcomeDialog page(window.files(), QString()); // not the window's own page
        QVERIFY(page.tutorialList()->count() >= 1);
        QSignalSpy requested(&page, &WelcomeDialog::tutorialRequested);
        page.openTutorial(0);
        QCOMPARE(requested.size(), 1);
        const QUrl url = requested.at(0).at(0).toUrl();
        QVERIFY2(QFile::exists(":" + url.path()), qPrintable(url.toString()));
        // Through the window: Help › Tutorials' page opens the guide at that page.
        auto* welcome = qobject_cast<WelcomeDialog*>(window.showWelcome());
        QVERIFY(welcome);
        welcome->openTutorial(0);
        auto* guide = window.findChild<UserGuideWindow*>();
        QVERIFY(guide && guide->isVisible());
        QCOMPARE(guide->currentPage(), url);
    }

    // Shown on the first start only, unless "Show at start" is checked; the box persists.
    void showAtStartPersists() {
        QVERIFY(WelcomeDialog::shouldShowAtStart()); // no settings: the first start
        TuningSession session;
        MainWindow window(&session);
        {
            WelcomeDialog page(window.files(), QString(), &window);
            QVERIFY(!page.showAtStartBox()->isChecked());
            page.show();
            QVERIFY(QTest::qWaitForWindowExposed(&page));
        }
        QVERIFY(!WelcomeDialog::shouldShowAtStart()); // shown once: not again
        {
            WelcomeDialog page(window.files(), QString(), &window);
            QTest::mouseClick(page.showAtStartBox(), Qt::LeftButton);
            QVERIFY(page.showAtStartBox()->isChecked());
        }
        QVERIFY(WelcomeDialog::shouldShowAtStart());
        {
            WelcomeDialog page(window.files(), QString(), &window);
            QVERIFY(page.showAtStartBox()->isChecked()); // read back from the settings
            QTest::mouseClick(page.showAtStartBox(), Qt::LeftButton);
        }
        QCOMPARE(QSettings().value(WelcomeDialog::kAtStartKey).toBool(), false);
        QVERIFY(!WelcomeDialog::shouldShowAtStart());
        WelcomeDialog again(window.files(), QString(), &window);
        QVERIFY(!again.showAtStartBox()->isChecked());
        // The window alone never shows it (main() decides, in its interactive path only).
        QVERIFY(window.findChildren<WelcomeDialog*>().isEmpty() ||
                !window.findChild<WelcomeDialog*>()->isVisible());
    }
};

QTEST_MAIN(TstUserGuide)
#include "tst_user_guide.moc"
