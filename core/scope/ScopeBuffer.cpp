#include "ScopeBuffer.h"

namespace DriveDesk {

bool ScopeBuffer::append(const ScopeSample &sample)
{
    if (!m_samples.append(sample))
        return false;
    m_pyramid.append(sample);
    return true;
}

bool ScopeBuffer::repeatsLast(const ScopeSample &sample) const
{
    return !m_samples.isEmpty() && m_samples.at(m_samples.count() - 1) == sample;
}

void ScopeBuffer::clear()
{
    m_samples.clear();
    m_pyramid.clear();
}

} // namespace DriveDesk
