// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/help/user_guide_window.h"

#include <QDesktopServices>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QListWidget>
#include <QPixmap>
#include <QResizeEvent>
#include <QSignalBlocker>
#include <QSplitter>
#include <QStyle>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextFragment>
#include <QTextImageFormat>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <vector>

namespace xyt::ui {

namespace {

/// The reference pages in the order a reader wants them; pages not named here follow by name.
const QStringList& userGuideReferenceOrder() {
    static const QStringList order{"cli.md",          "session-format.md", "exports.md",
                                   "equations.md",    "report.md",         "install.md",
                                   "architecture.md", "contributing.md"};
    return order;
}

/// The tutorials in the order the guide's index lists them (a reader goes from the papers to
/// the table's imperfections); pages not named here follow by name.
const QStringList& userGuideTutorialOrder() {
    static const QStringList order{"user-guide/index.md",
                                   "user-guide/braga-guillemin-truxal.md",
                                   "user-guide/patrick-pole-placement.md",
                                   "user-guide/log-to-firmware.md",
                                   "user-guide/ballbar.md",
                                   "user-guide/design-space-and-robustness.md",
                                   "user-guide/feedforward.md",
                                   "user-guide/friction.md",
                                   "user-guide/vibration.md",
                                   "user-guide/cross-coupling.md"};
    return order;
}

/// Sorts @p paths by their rank in @p order, the others after them by name.
void userGuideSortBy(QStringList& paths, const QStringList& order) {
    std::sort(paths.begin(), paths.end(), [&order](const QString& a, const QString& b) {
        const qsizetype ra = order.contains(a) ? order.indexOf(a) : order.size();
        const qsizetype rb = order.contains(b) ? order.indexOf(b) : order.size();
        return ra != rb ? ra < rb : a < b;
    });
}

/// Scales every image of @p browser's page down to the width the page has (never up): the
/// screenshots are 1366 px wide, wider than the guide's window, and a picture cut at the right
/// edge or a page that scrolls sideways is worse than a smaller picture (it keeps its aspect).
void userGuideFitImages(QTextBrowser* browser) {
    QTextDocument* document = browser->document();
    const double available = browser->viewport()->width() - 2.0 * document->documentMargin() - 4.0;
    if (available < 50.0)
        return;
    struct Placed {
        int position;
        int length;
        QTextImageFormat format;
    };
    std::vector<Placed> images;
    for (QTextBlock block = document->begin(); block.isValid(); block = block.next())
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextFragment fragment = it.fragment();
            if (fragment.isValid() && fragment.charFormat().isImageFormat())
                images.push_back({fragment.position(), fragment.length(),
                                  fragment.charFormat().toImageFormat()});
        }
    for (Placed& placed : images) {
        const QVariant resource =
            document->resource(QTextDocument::ImageResource, QUrl(placed.format.name()));
        QSize natural = resource.value<QImage>().size();
        if (natural.isEmpty())
            natural = resource.value<QPixmap>().size();
        if (natural.isEmpty())
            continue;
        const double width = std::min<double>(natural.width(), available);
        if (std::abs(placed.format.width() - width) < 0.5)
            continue;
        placed.format.setWidth(width);
        placed.format.setHeight(natural.height() * width / natural.width());
        QTextCursor cursor(document);
        cursor.setPosition(placed.position);
        cursor.setPosition(placed.position + placed.length, QTextCursor::KeepAnchor);
        cursor.setCharFormat(placed.format);
    }
}

/// The anchor GitHub gives a heading ("## Guillemin–Truxal PI (Braga et al.)" →
/// "guillemintruxal-pi-braga-et-al"): lower case, letters, digits, '-' and '_' kept, spaces
/// made '-', everything else dropped. The pages link to sections by it (`cli.md#export`).
QString userGuideHeadingSlug(const QString& heading) {
    QString slug;
    for (const QChar c : heading.trimmed().toLower()) {
        if (c.isLetterOrNumber() || c == u'-' || c == u'_')
            slug += c;
        else if (c == u' ')
            slug += u'-';
    }
    return slug;
}

/// Gives each heading of @p document its GitHub anchor name, so that links to a section work
/// here as on the web (Qt's Markdown reader names no heading).
void userGuideNameHeadings(QTextDocument* document) {
    for (QTextBlock block = document->begin(); block.isValid(); block = block.next()) {
        if (block.blockFormat().headingLevel() == 0 || block.text().isEmpty())
            continue;
        QTextCursor cursor(block);
        cursor.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
        QTextCharFormat named;
        named.setAnchor(true);
        named.setAnchorNames({userGuideHeadingSlug(block.text())});
        cursor.mergeCharFormat(named);
    }
}

bool userGuideIsMarkdown(const QUrl& url) {
    const QString name = url.path().toLower();
    return name.endsWith(".md") || name.endsWith(".markdown");
}

} // namespace

QUrl UserGuideWindow::docsUrl(const QString& pathUnderDocs) {
    QUrl url;
    url.setScheme("qrc");
    url.setPath("/docs/" + pathUnderDocs);
    return url;
}

QList<QUrl> UserGuideWindow::pages() {
    QStringList guide;
    QStringList reference;
    QDirIterator it(":/docs", {"*.md"}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next().mid(QStringLiteral(":/docs/").size());
        (path.startsWith("user-guide/") ? guide : reference).append(path);
    }
    // The guide: its index first, then the tutorials as the index lists them; the reference:
    // the known pages in reading order; in both, the others after them by name.
    userGuideSortBy(guide, userGuideTutorialOrder());
    userGuideSortBy(reference, userGuideReferenceOrder());
    QList<QUrl> urls;
    for (const QString& path : guide + reference)
        urls.append(docsUrl(path));
    return urls;
}

QUrl UserGuideWindow::homePage() {
    if (QFile::exists(":/docs/user-guide/index.md"))
        return docsUrl("user-guide/index.md");
    for (const QString& page : userGuideReferenceOrder())
        if (QFile::exists(":/docs/" + page))
            return docsUrl(page);
    const QList<QUrl> all = pages();
    return all.isEmpty() ? QUrl() : all.first();
}

QString UserGuideWindow::pageTitle(const QUrl& page) {
    QFile file(":" + page.path());
    if (file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        // The first level-one heading within the first lines (a page starts with it).
        for (int line = 0; line < 20 && !file.atEnd(); ++line) {
            const QString text = QString::fromUtf8(file.readLine()).trimmed();
            if (text.startsWith("# "))
                return text.mid(2).trimmed();
        }
    }
    return QFileInfo(page.path()).completeBaseName();
}

UserGuideWindow::UserGuideWindow(QWidget* parent) : QWidget(parent, Qt::Window) {
    setObjectName("userGuideWindow");
    setWindowTitle(tr("XY Tune user guide"));
    resize(1000, 720);

    back_ = new QToolButton(this);
    back_->setObjectName("userGuideBack");
    back_->setIcon(style()->standardIcon(QStyle::SP_ArrowBack));
    back_->setText(tr("Back"));
    back_->setToolTip(tr("Back to the page shown before (Alt+Left)"));
    back_->setShortcut(QKeySequence::Back);
    forward_ = new QToolButton(this);
    forward_->setObjectName("userGuideForward");
    forward_->setIcon(style()->standardIcon(QStyle::SP_ArrowForward));
    forward_->setText(tr("Forward"));
    forward_->setToolTip(tr("Forward to the page left with Back (Alt+Right)"));
    forward_->setShortcut(QKeySequence::Forward);
    home_ = new QToolButton(this);
    home_->setObjectName("userGuideHome");
    home_->setIcon(style()->standardIcon(QStyle::SP_DirHomeIcon));
    home_->setText(tr("Home"));
    home_->setToolTip(tr("The guide's first page: the list of tutorials"));
    for (QToolButton* button : {back_, forward_, home_})
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    back_->setEnabled(false);
    forward_->setEnabled(false);

    contents_ = new QListWidget(this);
    contents_->setObjectName("userGuideContents");
    contents_->setToolTip(tr("The pages of the guide: the tutorials, then the reference pages "
                             "(command line, session file, exports, equations, architecture)"));
    browser_ = new QTextBrowser(this);
    browser_->setObjectName("userGuideBrowser");
    browser_->setOpenLinks(false); // followLink decides: a bundled page here, the web outside

    // The contents: a heading row (not selectable) over each group.
    bool referenceStarted = false;
    const auto addHeading = [this](const QString& text) {
        auto* heading = new QListWidgetItem(text, contents_);
        QFont bold = heading->font();
        bold.setBold(true);
        heading->setFont(bold);
        heading->setFlags(Qt::NoItemFlags);
    };
    const QList<QUrl> all = pages();
    if (!all.isEmpty() && all.first().path().startsWith("/docs/user-guide/"))
        addHeading(tr("User guide"));
    for (const QUrl& page : all) {
        if (!referenceStarted && !page.path().startsWith("/docs/user-guide/")) {
            addHeading(tr("Reference"));
            referenceStarted = true;
        }
        auto* item = new QListWidgetItem(pageTitle(page), contents_);
        item->setData(Qt::UserRole, page);
        item->setToolTip(page.path().mid(1));
    }

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(back_);
    buttons->addWidget(forward_);
    buttons->addWidget(home_);
    buttons->addStretch(1);
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(contents_);
    splitter->addWidget(browser_);
    splitter->setStretchFactor(0, 0);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({240, 760});
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(buttons);
    layout->addWidget(splitter, 1);

    connect(back_, &QToolButton::clicked, browser_, &QTextBrowser::backward);
    connect(forward_, &QToolButton::clicked, browser_, &QTextBrowser::forward);
    connect(home_, &QToolButton::clicked, this, &UserGuideWindow::showHome);
    connect(browser_, &QTextBrowser::backwardAvailable, back_, &QToolButton::setEnabled);
    connect(browser_, &QTextBrowser::forwardAvailable, forward_, &QToolButton::setEnabled);
    connect(browser_, &QTextBrowser::anchorClicked, this, &UserGuideWindow::followLink);
    // (source() is still the page before while sourceChanged is emitted for a new page: the
    // signal's own URL is the page shown.)
    connect(browser_, &QTextBrowser::sourceChanged, this, [this](const QUrl& source) {
        const QUrl page = source.adjusted(QUrl::RemoveFragment);
        userGuideNameHeadings(browser_->document());
        userGuideFitImages(browser_);
        if (source.hasFragment())
            browser_->scrollToAnchor(source.fragment());
        markCurrent(page);
        const QString title =
            browser_->documentTitle().isEmpty() ? pageTitle(page) : browser_->documentTitle();
        setWindowTitle(tr("%1 – XY Tune user guide").arg(title));
    });
    connect(contents_, &QListWidget::currentItemChanged, this, [this](QListWidgetItem* item) {
        if (item && item->data(Qt::UserRole).isValid())
            showPage(item->data(Qt::UserRole).toUrl());
    });

    const QUrl home = homePage();
    if (home.isValid())
        showPage(home);
    else
        browser_->setMarkdown(tr("# No pages\n\nThis build of XY Tune holds no documentation "
                                 "pages (the folder docs/ was empty when it was built)."));
}

void UserGuideWindow::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    userGuideFitImages(browser_); // the page's width changed with the window's
}

void UserGuideWindow::showPage(const QUrl& page) {
    if (!page.isValid())
        return;
    browser_->setSource(page, userGuideIsMarkdown(page) ? QTextDocument::MarkdownResource
                                                        : QTextDocument::UnknownResource);
}

QUrl UserGuideWindow::currentPage() const {
    return browser_->source().adjusted(QUrl::RemoveFragment);
}

void UserGuideWindow::followLink(const QUrl& link) {
    const QUrl target = link.isRelative() ? browser_->source().resolved(link) : link;
    if (target.scheme() == "qrc") {
        if (target.adjusted(QUrl::RemoveFragment) == currentPage() && target.hasFragment())
            browser_->scrollToAnchor(target.fragment());
        else
            showPage(target);
        return;
    }
    QDesktopServices::openUrl(target); // a web page or a mail address: the system's program
}

void UserGuideWindow::markCurrent(const QUrl& page) {
    const QSignalBlocker blocker(contents_);
    for (int row = 0; row < contents_->count(); ++row)
        if (contents_->item(row)->data(Qt::UserRole).toUrl() == page) {
            contents_->setCurrentRow(row);
            return;
        }
    contents_->clearSelection();
}

} // namespace xyt::ui
