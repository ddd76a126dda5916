#pragma once

// qcustomplot.h, for a project built with QT_NO_FOREACH: two of its inline templates
// (QCustomPlot::plottableAt, itemAt) loop with Qt's foreach, which that switches off. They get
// a range-based for over the (unmodified) list instead, for this header only.
#include <QtGlobal>

#include <utility>

#if !defined(foreach)
#define foreach(variable, container) for (variable : std::as_const(container))
#define DRIVEDESK_QCUSTOMPLOT_FOREACH
#endif

#include <qcustomplot.h>

#ifdef DRIVEDESK_QCUSTOMPLOT_FOREACH
#undef foreach
#undef DRIVEDESK_QCUSTOMPLOT_FOREACH
#endif
