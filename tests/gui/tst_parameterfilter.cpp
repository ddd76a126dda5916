#include "../parameters/EditorSampleDrive.h"

#include "model/ParameterFilterModel.h"
#include "model/ParameterModel.h"

#include <QAbstractItemModelTester>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::EditorSample;

namespace {

QStringList visibleIds(const QAbstractItemModel &model)
{
    QStringList ids;
    for (int g = 0; g < model.rowCount(); ++g) {
        const QModelIndex group = model.index(g, 0);
        for (int row = 0; row < model.rowCount(group); ++row)
            ids << model.index(row, 0, group).data().toString();
    }
    return ids;
}

QStringList visibleGroups(const QAbstractItemModel &model)
{
    QStringList ids;
    for (int g = 0; g < model.rowCount(); ++g)
        ids << model.index(g, 0).data().toString().section(QLatin1Char(' '), 0, 0);
    return ids;
}

QStringList ids(std::initializer_list<const char *> list)
{
    QStringList result;
    for (const char *id : list)
        result << QString::fromLatin1(id);
    return result;
}

} // namespace

// Search as you type and the filters, over the parameter tree.
class TestParameterFilter : public QObject
{
    Q_OBJECT
private:
    ParameterModel m_model;
    ParameterFilterModel m_filter;

private slots:
    void init()
    {
        m_model.state()->setDescription(drive());
        m_model.setFavourites({});
        m_model.state()->setPasswordLevel(PasswordLevel::Supervisor);
        m_filter.setSourceModel(&m_model);
        m_filter.setFilterText({});
        m_filter.setDiffersFromDefaultOnly(false);
        m_filter.setFavouritesOnly(false);
        m_filter.setHideAboveLevel(false);
    }

    void passesTheModelTesterThroughFiltersUpdatesAndReset()
    {
        ParameterModel model;
        ParameterFilterModel filter;
        filter.setSourceModel(&model);
        QAbstractItemModelTester tester(&filter,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        model.state()->setDescription(drive());
        for (const char *text : { "o", "op", "op.1", "frequency", "zzz", "" })
            filter.setFilterText(QString::fromLatin1(text));
        filter.setFilterText(QStringLiteral("fcon"));
        model.state()->setValue(kState, 0, 0);
        model.state()->setValue(kState, 0, 66);
        filter.setDiffersFromDefaultOnly(true);
        model.state()->setValue(kMaxFrequency, 1, 5000);
        filter.setFavouritesOnly(true);
        model.setFavourite(kState, true);
        filter.setHideAboveLevel(true);
        model.state()->setPasswordLevel(PasswordLevel::CpReadOnly);
        filter.sort(ParameterModel::columnOfSet(0));
        model.state()->setDescription(drive());
        filter.setFilterText({});
        filter.setFavouritesOnly(false);
        filter.setDiffersFromDefaultOnly(false);
        model.state()->clear();
        QCOMPARE(filter.rowCount(), 0);
    }

    void withoutFiltersEverythingStays()
    {
        QVERIFY(!m_filter.isFiltering());
        QCOMPARE(visibleGroups(m_filter), ids({ "ru", "oP", "Pn", "dr" }));
        QCOMPARE(visibleIds(m_filter).size(), m_model.state()->description().parameterCount());
    }

    void searchesById()
    {
        m_filter.setFilterText(QStringLiteral("ru.3"));
        QCOMPARE(visibleIds(m_filter), ids({ "ru.03" }));
        m_filter.setFilterText(QStringLiteral("ru.03"));
        QCOMPARE(visibleIds(m_filter), ids({ "ru.03" }));
        m_filter.setFilterText(QStringLiteral("RU.03 "));
        QCOMPARE(visibleIds(m_filter), ids({ "ru.03" }));
        m_filter.setFilterText(QStringLiteral("op.1"));
        QCOMPARE(visibleIds(m_filter), ids({ "oP.10", "oP.11", "oP.12" }));
        QCOMPARE(visibleGroups(m_filter), ids({ "oP" }));
        m_filter.setFilterText(QStringLiteral("0405h"));
        QCOMPARE(visibleIds(m_filter), ids({ "Pn.05" }));
    }

    // Every form the command line takes finds the parameter it names.
    void searchesByIdInEveryForm()
    {
        for (const char *form : { "pn5", "PN05", "0x0405", "0x405", "405h" }) {
            m_filter.setFilterText(QString::fromLatin1(form));
            QVERIFY2(visibleIds(m_filter).contains(QStringLiteral("Pn.05")), form);
        }
        m_filter.setFilterText(QStringLiteral("pn5"));
        QCOMPARE(visibleIds(m_filter), ids({ "Pn.05" }));
        // A name is still a name: no group "xy", nothing named so.
        m_filter.setFilterText(QStringLiteral("xy5"));
        QVERIFY(visibleIds(m_filter).isEmpty());
    }

    void searchesByName()
    {
        m_filter.setFilterText(QStringLiteral("FREQ"));
        QCOMPARE(visibleIds(m_filter), ids({ "ru.03", "oP.10" }));
        QCOMPARE(visibleGroups(m_filter), ids({ "ru", "oP" }));
    }

    void searchesByShownValue()
    {
        m_filter.setFilterText(QStringLiteral("fcon"));
        QCOMPARE(visibleIds(m_filter), ids({ "ru.00" }));
        m_filter.setFilterText(QStringLiteral("60.00"));
        QCOMPARE(visibleIds(m_filter), ids({ "oP.10" })); // set 1
        m_filter.setFilterText(QStringLiteral("Released"));
        QCOMPARE(visibleIds(m_filter), ids({ "Pn.05" }));
        m_filter.setFilterText(QStringLiteral("00ffh"));
        QCOMPARE(visibleIds(m_filter), ids({ "Pn.06" }));
        m_filter.setFilterText(QStringLiteral("nothing like this"));
        QVERIFY(visibleGroups(m_filter).isEmpty());
    }

    void searchFollowsValueUpdates()
    {
        m_filter.setFilterText(QStringLiteral("fcon"));
        m_model.state()->setValue(kState, 0, 0); // noP
        QVERIFY(visibleGroups(m_filter).isEmpty());
        m_model.state()->setValue(kState, 0, 66);
        QCOMPARE(visibleIds(m_filter), ids({ "ru.00" }));
        m_model.setShowRawValues(true);
        m_filter.setFilterText(QStringLiteral("-4180"));
        QCOMPARE(visibleIds(m_filter), ids({ "ru.03" }));
    }

    void showsValuesThatDifferFromTheDefault()
    {
        // ru.00 and ru.03 differ too, but are read-only: no setting anyone changed.
        m_filter.setDiffersFromDefaultOnly(true);
        QCOMPARE(visibleIds(m_filter), ids({ "oP.10", "oP.12", "Pn.05" }));
        m_model.state()->setValue(kMaxFrequency, 1, 5000);
        QCOMPARE(visibleIds(m_filter), ids({ "oP.12", "Pn.05" }));
        m_model.state()->setValue(kRampTime, 0, 600);
        QCOMPARE(visibleIds(m_filter), ids({ "oP.11", "oP.12", "Pn.05" }));
        m_filter.setFilterText(QStringLiteral("oP"));
        QCOMPARE(visibleIds(m_filter), ids({ "oP.11", "oP.12" }));
    }

    void showsFavouritesOnly()
    {
        m_filter.setFavouritesOnly(true);
        QVERIFY(visibleIds(m_filter).isEmpty());
        m_model.setFavourite(kRampTime, true);
        QCOMPARE(visibleIds(m_filter), ids({ "oP.11" }));
        m_model.setFavourites({ kRampTime, kErrorMask });
        QCOMPARE(visibleIds(m_filter), ids({ "oP.11", "Pn.06" }));
        m_filter.setFilterText(QStringLiteral("mask"));
        QCOMPARE(visibleIds(m_filter), ids({ "Pn.06" }));
    }

    void hidesParametersAboveThePasswordLevelWhenAsked()
    {
        m_filter.setHideAboveLevel(true);
        QCOMPARE(visibleIds(m_filter).size(), 8);
        m_model.state()->setPasswordLevel(PasswordLevel::CpReadWrite);
        QVERIFY(!visibleIds(m_filter).contains(QStringLiteral("Pn.07")));
        QCOMPARE(visibleIds(m_filter).size(), 7);
        m_filter.setHideAboveLevel(false); // greyed instead
        QVERIFY(visibleIds(m_filter).contains(QStringLiteral("Pn.07")));
        m_filter.setHideAboveLevel(true);
        m_model.state()->setPasswordLevel(PasswordLevel::CpReadOnly);
        // Read-only parameters stay; those written from CP read/write on go.
        QCOMPARE(visibleIds(m_filter), ids({ "ru.00", "ru.03" }));
    }

    void sortsValuesByTheirRawNumbersAndKeepsGroupsInOrder()
    {
        m_filter.sort(ParameterModel::columnOfSet(0));
        QCOMPARE(visibleGroups(m_filter), ids({ "ru", "oP", "Pn", "dr" }));
        const QModelIndex op = m_filter.index(1, 0);
        QStringList order;
        for (int row = 0; row < m_filter.rowCount(op); ++row)
            order << m_filter.index(row, 0, op).data().toString();
        QCOMPARE(order, ids({ "oP.12", "oP.11", "oP.10" }));
        m_filter.sort(-1);
    }
};

QTEST_MAIN(TestParameterFilter)
#include "tst_parameterfilter.moc"
