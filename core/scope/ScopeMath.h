#pragma once

#include "ScopeMathDefinition.h"
#include "ScopeSeries.h"

namespace DriveDesk {

struct ScopeRecording;
struct ScopeSnapshot;

// A math channel's trace, or why there is none.
struct ScopeMathResult
{
    // Titled and in the unit that follow from the sources (scopeMathTitle(), scopeMathUnit()).
    // One value a sample of the first source, at its time; Difference and Sum leave out the
    // first source's samples outside the second's time span.
    ScopeSeries series;
    ScopeMathUnit unit;
    QString error; // empty when computed

    bool ok() const { return error.isEmpty(); }
};

// Computes a math channel from the recording's samples (all of them; the display values,
// ScopeChannel::toDisplay()). Pure: safe in any thread that owns the recording or a copy.
//
// - Derivative: at each sample the slope of the parabola through it and its neighbours
//   (second-order accurate on uneven steps, as numpy's gradient), the slope to the one
//   neighbour at either end; in the unit per second. Neighbours in the same ms are passed over
//   for the nearest at another time: a drive polled faster than its 1 ms clock gives several
//   samples a ms. Needs samples at two times at least.
// - Integral: the area under the line through the samples (trapezoids) from the first sample,
//   in the unit times seconds; 0 at the first sample.
// - Difference, Sum: the first source's sample minus or plus the second's at the same time;
//   where the second has no sample at that time, its line between the samples either side.
// - MovingAverage: the plain mean of the samples in a window centred on each sample (for an
//   even count of samples one more before than after), fewer at either end.
ScopeMathResult computeScopeMath(const ScopeMathDefinition &definition,
                                 const ScopeRecording &recording);
// The same from a snapshot of a recording, in any thread.
ScopeMathResult computeScopeMath(const ScopeMathDefinition &definition,
                                 const ScopeSnapshot &snapshot);
// The same from traces of any origin (a CSV export's columns, another math channel): `second`
// for Difference and Sum.
ScopeMathResult computeScopeMath(const ScopeMathDefinition &definition, const ScopeSeries &first,
                                 const ScopeSeries *second = nullptr);

} // namespace DriveDesk
