// SPDX-License-Identifier: BSD-3-Clause
// The Qt API differences between the releases ShadingLab builds against
// (Qt 5.15 on Debian 12, Qt 6.8 on 13, Qt 6.11 on unstable), absorbed here
// so no other file tests Qt's version.
#ifndef shadinglab_QtCompat_h
#define shadinglab_QtCompat_h

#include <QtGlobal>

// Qt Charts: Qt 5 declares its classes in namespace QtCharts, Qt 6 in Qt's
// own namespace. The widgets write QtCharts::QChart (and `using namespace
// QtCharts;`) and get the right class from either.
#if QT_VERSION >= QT_VERSION_CHECK(6, 0, 0)
QT_BEGIN_NAMESPACE
class QChart;
class QChartView;
class QValueAxis;
QT_END_NAMESPACE
namespace QtCharts
{
using ::QChart;
using ::QChartView;
using ::QValueAxis;
}
#else
namespace QtCharts
{
class QChart;
class QChartView;
class QValueAxis;
}
#endif

#endif
