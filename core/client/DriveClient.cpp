#include "DriveClient.h"

#include "ClientWorker.h"
#include "ScanJob.h"
#include "ValueRequests.h"

#include <QMetaMethod>
#include <QThread>

namespace DriveDesk {

namespace {

template<typename T>
std::shared_ptr<QPromise<T>> startedPromise()
{
    auto promise = std::make_shared<QPromise<T>>();
    promise->start();
    return promise;
}

} // namespace

DriveClient::DriveClient(ConnectionSettings settings, LinkMaker makeLink, ClientOptions options,
                         QObject *parent)
    : QObject(parent)
    , m_settings(std::move(settings))
    , m_options(options)
    , m_makeLink(std::move(makeLink))
{
    qRegisterMetaType<Reply>();
    qRegisterMetaType<TrafficRecord>();
    qRegisterMetaType<DriveClient::State>();

    m_thread = new QThread; // not a child: it must outlive everything the worker does
    m_thread->setObjectName(QStringLiteral("DriveDesk client: %1").arg(m_settings.displayName()));
    m_worker = new ClientWorker(m_settings, m_options, m_makeLink);
    // isSignalConnected() takes the signals' lock: safe from the worker's thread, and this
    // object outlives the worker (the destructor joins its thread).
    m_worker->setTrafficWanted(
        [this, traffic = QMetaMethod::fromSignal(&DriveClient::traffic)] {
            return isSignalConnected(traffic);
        });
    m_worker->moveToThread(m_thread);
    connect(m_thread, &QThread::started, m_worker, &ClientWorker::init);
    connect(m_thread, &QThread::finished, m_worker, &QObject::deleteLater);

    connect(m_worker, &ClientWorker::stateChanged, this, &DriveClient::setState);
    connect(m_worker, &ClientWorker::connected, this, &DriveClient::connected);
    connect(m_worker, &ClientWorker::connectionFailed, this, &DriveClient::connectionFailed);
    connect(m_worker, &ClientWorker::linkLost, this, &DriveClient::linkLost);
    connect(m_worker, &ClientWorker::driveSilentChanged, this, &DriveClient::setDriveSilent);
    connect(m_worker, &ClientWorker::baudRateFound, this, &DriveClient::onBaudRateFound);
    connect(m_worker, &ClientWorker::driveStoppedAnswering, this,
            &DriveClient::driveStoppedAnswering);
    connect(m_worker, &ClientWorker::traffic, this, &DriveClient::traffic);
    m_thread->start();
}

DriveClient::~DriveClient()
{
    // The worker finishes every open request as Cancelled when it is deleted on `finished`.
    m_thread->quit();
    m_thread->wait();
    delete m_thread;
}

void DriveClient::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    emit stateChanged(state);
}

void DriveClient::onBaudRateFound(qint32 baudRate)
{
    m_settings.baudRate = baudRate;
    m_settings.automaticBaudRate = false; // settings() names the rate; a reconnect searches again
    emit baudRateFound(baudRate);
}

void DriveClient::setDriveSilent(bool silent)
{
    if (m_driveSilent == silent)
        return;
    m_driveSilent = silent;
    emit driveSilentChanged(silent);
}

void DriveClient::connectToDrive()
{
    QMetaObject::invokeMethod(m_worker, &ClientWorker::connectToDrive, Qt::QueuedConnection);
}

void DriveClient::disconnectFromDrive()
{
    QMetaObject::invokeMethod(m_worker, &ClientWorker::disconnectFromDrive, Qt::QueuedConnection);
}

void DriveClient::cancelAll()
{
    QMetaObject::invokeMethod(m_worker, &ClientWorker::cancelAll, Qt::QueuedConnection);
}

QFuture<Reply> DriveClient::send(const Telegram &request)
{
    auto promise = startedPromise<Reply>();
    QFuture<Reply> future = promise->future();
    ClientWorker *worker = m_worker;
    QMetaObject::invokeMethod(
        worker, [worker, request, promise] { worker->submitForFuture(request, promise); },
        Qt::QueuedConnection);
    return future;
}

void DriveClient::setIdleCheckAddress(quint16 address)
{
    QMetaObject::invokeMethod(
        m_worker, [worker = m_worker, address] { worker->setIdleCheckAddress(address); },
        Qt::QueuedConnection);
}

QFuture<Reply> DriveClient::readValue(quint16 address, quint8 setMask)
{
    return send(ValueRequests::read(address, setMask));
}

QFuture<Reply> DriveClient::writeValue(quint16 address, qint32 value, quint8 setMask)
{
    return send(ValueRequests::write(address, value, setMask));
}

QFuture<Reply> DriveClient::readValueStandard(quint16 address, quint8 set)
{
    return send(ValueRequests::readStandard(m_settings.protocol, address, set));
}

QFuture<Reply> DriveClient::writeValueStandard(quint16 address, qint32 value, quint8 set)
{
    return send(ValueRequests::writeStandard(m_settings.protocol, address, value, set));
}

QFuture<Reply> DriveClient::resetToDefault(quint16 address, quint8 setMask)
{
    return send(ValueRequests::resetToDefault(address, setMask));
}

QFuture<Reply> DriveClient::readScope()
{
    return send(Telegram::request(Service::Scope, Access::Read, ScopeData{}));
}

void DriveClient::start(std::shared_ptr<RequestJobBase> job, int driveAddress)
{
    ClientWorker *worker = m_worker;
    QMetaObject::invokeMethod(
        worker, [worker, job = std::move(job), driveAddress] { worker->runJob(job, driveAddress); },
        Qt::QueuedConnection);
}

void DriveClient::resume(const std::weak_ptr<RequestJobBase> &job)
{
    QMetaObject::invokeMethod(
        m_worker,
        [job] {
            if (const auto running = job.lock())
                running->resumed();
        },
        Qt::QueuedConnection);
}

void DriveClient::stopScan()
{
    ClientWorker *worker = m_worker;
    QMetaObject::invokeMethod(worker, [worker] { worker->finishJobsEarly(); },
                              Qt::QueuedConnection);
}

QFuture<DriveDescription> DriveClient::scan(ScanOptions options)
{
    ClientWorker *worker = m_worker;
    ConnectionSettings settings = m_settings;
    const int driveAddress = options.driveAddress;
    if (driveAddress >= 0 && settings.protocol != Protocol::Hsp5)
        settings.driveAddress = driveAddress;
    return run(std::make_shared<ScanJob>(
                   std::move(options), settings,
                   [worker] { return worker->connectionDescription(); }, worker),
               driveAddress);
}

} // namespace DriveDesk
