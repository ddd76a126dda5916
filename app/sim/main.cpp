// drivedesk-sim: simulated KEB drives on TCP or on a pseudo-terminal, for DriveDesk and for
// any other program that talks HSP5 or DIN66019(II).
#include "bus/SimulatedBus.h"
#include "bus/SimulatorServer.h"
#include "link/ConnectionOptions.h"
#include "link/SignalNotifier.h"
#include "link/TcpTarget.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QHostAddress>

#include <csignal>
#include <utility>
#include <cstdio>

using namespace DriveDesk;

namespace {

constexpr int kBadOption = 2;
constexpr int kCannotServe = 1;

QString tr(const char *text)
{
    return QCoreApplication::translate("drivedesk-sim", text);
}

QCommandLineOption option(const char *name, const char *help, const char *valueName = nullptr)
{
    QCommandLineOption result(QString::fromLatin1(name), tr(help));
    if (valueName)
        result.setValueName(tr(valueName));
    return result;
}

void say(const QString &text)
{
    std::fprintf(stdout, "drivedesk-sim: %s\n", qPrintable(text));
    std::fflush(stdout);
}

int complain(const QString &text, int code = kBadOption)
{
    std::fprintf(stderr, "drivedesk-sim: %s\n", qPrintable(text));
    return code;
}

struct Options {
    Protocol protocol = Protocol::Hsp5;
    SimulationOptions simulation;
    QString tcpHost;
    int tcpPort = -1;
    QString ptyPath;
};

bool parseRate(const QCommandLineParser &parser, const QString &name, double *value,
               QString *error)
{
    if (!parser.isSet(name))
        return true;
    bool ok = false;
    const double rate = parser.value(name).toDouble(&ok);
    if (!ok || !(rate >= 0.0 && rate <= 1.0)) {
        *error = tr("--%1 \"%2\" is not a rate from 0 to 1").arg(name, parser.value(name));
        return false;
    }
    *value = rate;
    return true;
}

bool parseListen(const QString &text, Options *options, QString *error)
{
    if (!text.startsWith(QLatin1String("tcp:"))) {
        *error = tr("--listen \"%1\" is not tcp:HOST:PORT (e.g. tcp:127.0.0.1:5020)").arg(text);
        return false;
    }
    // The client's syntax (core/link/TcpTarget), with port 0 for any free one.
    QString reason;
    const std::optional<TcpTarget> target
        = TcpTarget::parse(text.mid(4), TcpTarget::Port::AnyFree, &reason);
    if (!target) {
        *error = QStringLiteral("--listen: %1").arg(reason);
        return false;
    }
    const QString host = target->host;
    const quint16 port = target->port;
    const bool named = host == QLatin1String("*")
                       || host.compare(QLatin1String("localhost"), Qt::CaseInsensitive) == 0;
    if (!named && QHostAddress(host).isNull()) {
        *error = tr("--listen: \"%1\" is not an IP address (give e.g. 127.0.0.1, localhost or *)")
                     .arg(host);
        return false;
    }
    options->tcpHost = host;
    options->tcpPort = int(port);
    return true;
}

// Drive addresses, repeated or as a list (1,2,3), each once.
bool parseAddressList(const QCommandLineParser &parser, const QString &name, QList<int> *addresses,
                      QString *error)
{
    for (const QString &value : parser.values(name)) {
        for (const QString &item : value.split(QLatin1Char(','))) {
            bool ok = false;
            const int address = item.trimmed().toInt(&ok);
            if (!ok || address < 0 || address > ConnectionSettings::kMaxDriveAddress) {
                *error = tr("--%1 \"%2\" is not a drive address from 0 to %3")
                             .arg(name, item)
                             .arg(ConnectionSettings::kMaxDriveAddress);
                return false;
            }
            if (addresses->contains(address)) {
                *error = tr("--%1 %2 is given twice").arg(name).arg(address);
                return false;
            }
            addresses->append(address);
        }
    }
    return true;
}

// --other-kind and --unidentified: drives of the bus, one kind each.
bool parseKinds(const QCommandLineParser &parser, Options *options, QString *error)
{
    SimulationOptions &simulation = options->simulation;
    const QString other = QStringLiteral("other-kind");
    const QString unidentified = QStringLiteral("unidentified");
    if (!parseAddressList(parser, other, &simulation.otherKindAddresses, error)
        || !parseAddressList(parser, unidentified, &simulation.unidentifiedAddresses, error))
        return false;
    for (const auto &[name, addresses] :
         {std::pair{other, simulation.otherKindAddresses},
          std::pair{unidentified, simulation.unidentifiedAddresses}}) {
        for (int address : addresses) {
            if (!simulation.driveAddresses.contains(address)) {
                *error = tr("--%1 %2: there is no drive %2 (see --address)").arg(name).arg(address);
                return false;
            }
            if (name == other && simulation.unidentifiedAddresses.contains(address)) {
                *error = tr("drive %1 is given both --other-kind and --unidentified").arg(address);
                return false;
            }
        }
    }
    return true;
}

bool parseAddresses(const QCommandLineParser &parser, Options *options, QString *error)
{
    QList<int> addresses;
    if (!parseAddressList(parser, QStringLiteral("address"), &addresses, error))
        return false;
    if (addresses.isEmpty())
        addresses = {1};
    if (options->protocol == Protocol::Hsp5 && addresses.size() > 1) {
        *error = tr("HSP5 is point to point: give one --address, or use --protocol din66019ii");
        return false;
    }
    options->simulation.driveAddresses = addresses;
    return true;
}

bool parseOptions(const QCommandLineParser &parser, Options *options, QString *error)
{
    if (!parser.positionalArguments().isEmpty()) {
        *error = tr("unexpected argument \"%1\"").arg(parser.positionalArguments().constFirst());
        return false;
    }
    if (parser.isSet(QStringLiteral("listen")) == parser.isSet(QStringLiteral("pty"))) {
        *error = tr("give either --listen tcp:HOST:PORT or --pty PATH");
        return false;
    }
    if (parser.isSet(QStringLiteral("listen"))
        && !parseListen(parser.value(QStringLiteral("listen")), options, error))
        return false;
    options->ptyPath = parser.value(QStringLiteral("pty"));
    if (parser.isSet(QStringLiteral("pty")) && options->ptyPath.isEmpty()) {
        *error = tr("--pty needs a path for the link, e.g. /tmp/drive");
        return false;
    }
    if (parser.isSet(QStringLiteral("protocol"))) {
        const QString name = parser.value(QStringLiteral("protocol"));
        const std::optional<Protocol> protocol = protocolFromName(name);
        if (!protocol) {
            *error = tr("--protocol \"%1\" is unknown: give hsp5, din66019ii or din66019")
                         .arg(name);
            return false;
        }
        options->protocol = *protocol;
    }
    if (!parseAddresses(parser, options, error) || !parseKinds(parser, options, error))
        return false;

    SimulationOptions &simulation = options->simulation;
    qint64 latency = simulation.replyLatencyUs;
    qint64 baud = simulation.baudRate;
    qint64 parameters = simulation.parameterCount;
    qint64 delayMs = simulation.delayMs;
    qint64 seed = simulation.seed;
    const auto parseInteger = [&parser, error](const char *name, qint64 low, qint64 high,
                                               qint64 *value) {
        return ConnectionOptions::integer(parser, QCommandLineOption(QString::fromLatin1(name)),
                                          low, high, value, error);
    };
    if (!parseInteger("latency-us", 0, 60'000'000, &latency)
        || !parseInteger("baud", 50, 10'000'000, &baud)
        || !parseInteger("parameters", 0, 65535, &parameters)
        || !parseInteger("delay-ms", 0, 600'000, &delayMs)
        || !parseInteger("seed", 0, 0xFFFFFFFFLL, &seed)
        || !parseRate(parser, QStringLiteral("corrupt-rate"), &simulation.corruptByteRate, error)
        || !parseRate(parser, QStringLiteral("drop-rate"), &simulation.dropByteRate, error)
        || !parseRate(parser, QStringLiteral("flip-rate"), &simulation.flipByteRate, error)
        || !parseRate(parser, QStringLiteral("delay-rate"), &simulation.delayRate, error)
        || !parseRate(parser, QStringLiteral("busy-rate"), &simulation.busyRate, error)
        || !parseRate(parser, QStringLiteral("unsolicited-rate"), &simulation.unsolicitedRate,
                      error))
        return false;
    if (simulation.unsolicitedRate > 0 && options->protocol != Protocol::Hsp5) {
        *error = tr("--unsolicited-rate: only HSP5 drives start requests of their own");
        return false;
    }
    simulation.replyLatencyUs = int(latency);
    simulation.baudRate = qint32(baud);
    simulation.parameterCount = int(parameters);
    simulation.delayMs = int(delayMs);
    simulation.seed = quint32(seed);
    simulation.paced = parser.isSet(QStringLiteral("pace"));
    simulation.hsp5Extensions = parser.isSet(QStringLiteral("hsp5-extensions"));
    if (simulation.hsp5Extensions && options->protocol != Protocol::Hsp5) {
        *error = tr("--hsp5-extensions is for --protocol hsp5");
        return false;
    }
    return true;
}

QString drivesText(const Options &options)
{
    QStringList addresses;
    const SimulationOptions &simulation = options.simulation;
    for (int address : simulation.driveAddresses) {
        if (simulation.otherKindAddresses.contains(address))
            addresses.append(tr("%1 (other kind)").arg(address));
        else if (simulation.unidentifiedAddresses.contains(address))
            addresses.append(tr("%1 (unidentified)").arg(address));
        else
            addresses.append(QString::number(address));
    }
    const QString protocol = protocolName(options.protocol).toUpper();
    return addresses.size() == 1
               ? tr("%1 drive %2").arg(protocol, addresses.constFirst())
               : tr("%1 drives %2").arg(protocol, addresses.join(QStringLiteral(", ")));
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("drivedesk-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIVEDESK_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        tr("Simulated KEB drives for DriveDesk, served over TCP or a pseudo-terminal."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOptions({
        option("listen", "Serve over TCP, e.g. tcp:127.0.0.1:5020 (port 0: any free one).",
               "tcp:HOST:PORT"),
        option("pty", "Serve over a pseudo-terminal linked at PATH.", "PATH"),
        option("protocol", "hsp5 (default), din66019ii or din66019.", "NAME"),
        option("address", "Drive address 0..239; repeat it or give a list (1,2,3) for several "
                          "drives on one DIN bus.", "N"),
        option("latency-us", "Time from the end of a request to its reply (default 1000).", "US"),
        option("baud", "Baud rate for --pace (default 38400).", "N"),
        option("pace", "Send and receive at the baud rate."),
        option("hsp5-extensions", "HSP5: also know DriveDesk's services 13, 14, 19-21 and 51-53 "
                                  "(default: only those of the HSP5 specification)."),
        option("parameters", "Pad the drive to N parameters (0: the standard F5).", "N"),
        option("other-kind", "The drives at these addresses run other software: a higher "
                             "version and more parameters.", "N"),
        option("unidentified", "The drives at these addresses have no identification "
                               "parameters (not an F5).", "N"),
        option("corrupt-rate", "Chance per byte of one flipped bit, flagged as a parity error.",
               "RATE"),
        option("flip-rate", "Chance per byte of one flipped bit that arrives unflagged, as on "
                            "a line without parity (both directions).", "RATE"),
        option("drop-rate", "Chance per byte of losing it.", "RATE"),
        option("delay-rate", "Chance per reply of holding it back by --delay-ms.", "RATE"),
        option("delay-ms", "How long a delayed reply is held back (default 50).", "MS"),
        option("busy-rate", "Chance per request of answering busy (ack 6).", "RATE"),
        option("unsolicited-rate", "HSP5: chance per reply of a request from the drive first.",
               "RATE"),
        option("seed", "Seed of the fault generator (default 1).", "N"),
    });
    if (!parser.parse(QCoreApplication::arguments()))
        return complain(parser.errorText() + tr(" (see --help)"));
    if (parser.isSet(QStringLiteral("help")))
        parser.showHelp(0);
    if (parser.isSet(QStringLiteral("version")))
        parser.showVersion();

    Options options;
    QString error;
    if (!parseOptions(parser, &options, &error))
        return complain(error);

    SignalNotifier signalNotifier;
    if (!signalNotifier.watch({SIGINT, SIGTERM, SIGUSR1}))
        return complain(tr("cannot set up signal handling"), kCannotServe);
    SimulatorServer server(options.protocol, options.simulation);
    // SIGUSR1 freezes the drives (the connection stays open, nothing is answered) and thaws
    // them again: a drive that stops answering, on demand.
    QObject::connect(&signalNotifier, &SignalNotifier::caught, &app, [&server](int signal) {
        if (signal == SIGUSR1) {
            server.bus().setSilent(!server.bus().isSilent());
            say(server.bus().isSilent() ? tr("the drives stopped answering (SIGUSR1 again: answer)")
                                        : tr("the drives answer again"));
            return;
        }
        QCoreApplication::quit();
    });

    const bool listening = options.tcpPort >= 0
                               ? server.listenTcp(options.tcpHost, quint16(options.tcpPort), &error)
                               : server.listenPty(options.ptyPath, &error);
    if (!listening)
        return complain(error, kCannotServe);
    int exitCode = 0;
    QObject::connect(&server, &SimulatorServer::failed, &app, [&exitCode](const QString &reason) {
        complain(reason);
        exitCode = kCannotServe;
        QCoreApplication::quit();
    });
    QObject::connect(&server, &SimulatorServer::clientConnected, &app,
                     [](const QString &peer) { say(tr("operator connected from %1").arg(peer)); });
    QObject::connect(&server, &SimulatorServer::clientDisconnected, &app,
                     [](const QString &peer) { say(tr("operator %1 disconnected").arg(peer)); });

    QString where = server.addresses().join(QStringLiteral(", "));
    if (!options.ptyPath.isEmpty())
        where += QStringLiteral(" (%1)").arg(server.ptyDevice());
    say(tr("%1 listening on %2").arg(drivesText(options), where));

    const int loopResult = app.exec();
    server.close();
    say(tr("stopped"));
    return exitCode != 0 ? exitCode : loopResult;
}
