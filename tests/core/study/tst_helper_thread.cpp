// SPDX-License-Identifier: GPL-3.0-or-later
// runAlongside (core/study/helper_thread.h): both tasks run, on two threads when the helper is
// free (the helper's thread id differs from the caller's), on the caller when another caller
// holds it; exceptions of either reach the caller after both finished; many callers at once
// (four threads, 200 calls each) all get both of their tasks run exactly once.
#include "core/study/helper_thread.h"

#include <QTest>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace xyt;

class TstHelperThread : public QObject {
    Q_OBJECT
private slots:
    void runsBothTasksOnTwoThreads();
    void exceptionsReachTheCaller();
    void concurrentCallersEachRunBoth();
};

void TstHelperThread::runsBothTasksOnTwoThreads() {
    std::thread::id there, here;
    for (int repeat = 0; repeat < 3; ++repeat) { // the helper is reused, not restarted
        runAlongside([&] { there = std::this_thread::get_id(); },
                     [&] { here = std::this_thread::get_id(); });
        QVERIFY(here == std::this_thread::get_id());
        QVERIFY(there != std::this_thread::get_id());
    }
}

void TstHelperThread::exceptionsReachTheCaller() {
    bool hereRan = false, thereRan = false;
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, runAlongside(
                                                     [&] {
                                                         thereRan = true;
                                                         throw std::runtime_error("there");
                                                     },
                                                     [&] { hereRan = true; }));
    QVERIFY(hereRan && thereRan);
    hereRan = thereRan = false;
    try {
        runAlongside(
            [&] {
                thereRan = true;
                throw std::logic_error("there");
            },
            [&] {
                hereRan = true;
                throw std::runtime_error("here");
            });
        QFAIL("no exception");
    } catch (const std::runtime_error& e) {
        QCOMPARE(QString(e.what()), QString("here")); // the caller's first
    }
    QVERIFY(hereRan && thereRan);
    // The helper still works after its task threw.
    int sum = 0;
    runAlongside([&] { sum += 1; }, [&] { sum += 2; });
    QCOMPARE(sum, 3);
}

void TstHelperThread::concurrentCallersEachRunBoth() {
    constexpr int kThreads = 4, kCalls = 200;
    std::atomic<int> theres{0}, heres{0};
    std::vector<std::thread> callers;
    for (int t = 0; t < kThreads; ++t)
        callers.emplace_back([&] {
            for (int i = 0; i < kCalls; ++i)
                runAlongside([&] { theres.fetch_add(1); }, [&] { heres.fetch_add(1); });
        });
    for (auto& c : callers)
        c.join();
    QCOMPARE(theres.load(), kThreads * kCalls);
    QCOMPARE(heres.load(), kThreads * kCalls);
}

QTEST_APPLESS_MAIN(TstHelperThread)
#include "tst_helper_thread.moc"
