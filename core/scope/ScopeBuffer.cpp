#include "ScopeBuffer.h"

namespace DriveDesk {

bool ScopeBuffer::append(const ScopeSample &sample)
{
    if (!m_samples.append(sample))
        return false;
    m_pyramid.append(sample);
    return true;
}

void ScopeBuffer::clear()
{
    m_samples.clear();
    m_pyramid.clear();
}

} // namespace DriveDesk
