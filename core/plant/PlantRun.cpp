#include "PlantRun.h"

#include "PlantLinkRun.h"

#include <QDir>
#include <QTimer>

#include <algorithm>

namespace DriveDesk {

PlantRun::PlantRun(Plant plant, Task task, QString directory, LinkMaker makeLink, QObject *parent)
    : QObject(parent)
    , m_plant(std::move(plant))
    , m_task(task)
    , m_directory(std::move(directory))
    , m_makeLink(std::move(makeLink))
{}

PlantRun::~PlantRun() = default;

QString PlantRun::fileFor(const QString &directory, const PlantLink &link, int address)
{
    const QString name = link.protocol == Protocol::Hsp5 || address < 0
                             ? link.name
                             : QStringLiteral("%1-%2").arg(link.name).arg(address);
    return QDir(directory).filePath(name + QStringLiteral(".json"));
}

bool PlantRun::isRunning() const
{
    return m_linksRunning > 0;
}

QList<PlantDrive> PlantRun::drives() const
{
    QList<PlantDrive> all;
    for (const PlantLinkRun *link : m_links)
        all += link->drives();
    return all;
}

void PlantRun::start()
{
    if (m_started)
        return;
    m_started = true;
    PlantJob job;
    job.task = m_task;
    job.directory = m_directory;
    job.makeLink = m_makeLink;
    job.clientOptions = m_clientOptions;
    job.reading = m_reading;
    job.language = m_language;
    job.dryRun = m_dryRun;
    job.force = m_force;
    job.journal = m_journal;
    for (qsizetype i = 0; i < m_plant.links.size(); ++i) {
        auto *link = new PlantLinkRun(m_plant.links.at(i), job, this);
        const QString name = m_plant.links.at(i).name;
        connect(link, &PlantLinkRun::progress, this,
                [this, name](int address, int percent, const QString &what) {
                    emit progress(name, address, percent, what);
                });
        connect(link, &PlantLinkRun::driveDone, this, &PlantRun::driveDone);
        connect(link, &PlantLinkRun::finished, this, [this, link, i] {
            // A search that went to the end names the drives the plant has there.
            m_plant.links[i] = link->link();
            if (--m_linksRunning == 0)
                emit finished();
        });
        m_links.append(link);
    }
    m_linksRunning = int(m_links.size());
    if (m_links.isEmpty())
        QTimer::singleShot(0, this, &PlantRun::finished);
    for (PlantLinkRun *link : std::as_const(m_links))
        link->start();
}

void PlantRun::stop()
{
    if (m_stopping || !isRunning())
        return;
    m_stopping = true;
    for (PlantLinkRun *link : std::as_const(m_links))
        link->stop();
}

} // namespace DriveDesk
