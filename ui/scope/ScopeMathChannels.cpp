#include "ScopeMathChannels.h"

#include "client/WhenFinished.h"
#include "scope/ScopeMath.h"
#include "scope/ScopeRecording.h"
#include "scope/ScopeSnapshot.h"

#include <QtConcurrent/QtConcurrentRun>

#include <utility>

namespace DriveDesk {

struct ScopeMathChannels::Request
{
    ScopeSnapshot snapshot;
    QList<ScopeMathDefinition> definitions;
    quint64 generation = 0;
};

ScopeMathChannels::ScopeMathChannels(QObject *parent)
    : QObject(parent)
{ }

void ScopeMathChannels::compute(const ScopeRecording &recording, qsizetype sampleCount)
{
    ++m_generation;
    if (recording.math.isEmpty()) {
        m_waiting.reset();
        const bool had = !m_series.isEmpty() || !m_errors.isEmpty();
        m_series.clear();
        m_levels.clear();
        m_errors.clear();
        if (had)
            emit seriesChanged();
        return;
    }
    auto request = std::make_shared<Request>();
    request->snapshot = scopeSnapshot(recording, sampleCount);
    request->definitions = recording.math;
    request->generation = m_generation;
    if (m_running)
        m_waiting = std::move(request);
    else
        start(std::move(request));
}

void ScopeMathChannels::start(std::shared_ptr<const Request> request)
{
    m_running = true;
    const auto work = [request] {
        Result result;
        for (const ScopeMathDefinition &definition : request->definitions) {
            ScopeMathResult computed = computeScopeMath(definition, request->snapshot);
            if (computed.ok()) {
                auto series = std::make_shared<const ScopeSeries>(std::move(computed.series));
                result.levels << std::make_shared<const ScopeSeriesLevels>(*series);
                result.series << std::move(series);
            } else {
                result.errors << computed.error;
            }
        }
        return result;
    };
    const quint64 generation = request->generation;
    const auto done = [this, generation](const Result &result) {
        m_running = false;
        if (generation == m_generation) {
            m_series = result.series;
            m_levels = result.levels;
            m_errors = result.errors;
        }
        if (m_waiting) {
            start(std::exchange(m_waiting, nullptr));
        } else if (generation == m_generation) {
            emit seriesChanged();
        }
    };
    whenFinished(QtConcurrent::run(work), this, done, [done] { done({}); });
}

} // namespace DriveDesk
