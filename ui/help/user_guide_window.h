// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>
#include <QUrl>
#include <QWidget>

class QListWidget;
class QTextBrowser;
class QToolButton;

namespace xyt::ui {

/**
 * Help › User guide: the Markdown pages under docs/ (the tutorials of docs/user-guide and the
 * reference pages), bundled in the Qt resource system at :/docs, drawn by a QTextBrowser
 * (QTextDocument::MarkdownResource). Relative links between pages (`cli.md`,
 * `../exports.md#...`) and images (`../images/x.png`) resolve against the page shown, so the
 * guide works offline and installed; links to the web open in the system's browser. A
 * contents list on the left names every page; back, forward and home buttons as a browser's.
 */
class UserGuideWindow : public QWidget {
    Q_OBJECT
public:
    explicit UserGuideWindow(QWidget* parent = nullptr);

    /// Every page bundled under :/docs, as qrc URLs: the user guide's pages (index first), then
    /// the reference pages, each group by file name.
    static QList<QUrl> pages();
    /// The page opened first and by Home: docs/user-guide/index.md when it is bundled, else the
    /// first of the reference pages that is (cli.md, session-format.md, ...).
    static QUrl homePage();
    /// The title of a bundled page: its first "# " heading, else its file name.
    static QString pageTitle(const QUrl& page);

    /// Shows @p page (a qrc URL, or a path relative to :/docs such as "cli.md").
    void showPage(const QUrl& page);
    void showPage(const QString& pathUnderDocs) { showPage(docsUrl(pathUnderDocs)); }
    void showHome() { showPage(homePage()); }
    /// The page shown now (without its fragment).
    QUrl currentPage() const;

    QTextBrowser* browser() const { return browser_; }
    QListWidget* contents() const { return contents_; }
    QToolButton* backButton() const { return back_; }
    QToolButton* forwardButton() const { return forward_; }
    QToolButton* homeButton() const { return home_; }

    /// qrc:/docs/<path>.
    static QUrl docsUrl(const QString& pathUnderDocs);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    /// A link clicked in a page: a bundled page is shown, a web address opened outside.
    void followLink(const QUrl& link);
    /// Selects @p page in the contents list (without following the selection).
    void markCurrent(const QUrl& page);

    QTextBrowser* browser_ = nullptr;
    QListWidget* contents_ = nullptr;
    QToolButton* back_ = nullptr;
    QToolButton* forward_ = nullptr;
    QToolButton* home_ = nullptr;
};

} // namespace xyt::ui
