// The registered export formats, one function per format file (registry.cpp lists them).
#pragma once
#include "numeric/export/export_format.hpp"

namespace scalcal {

ExportFormat json_format();
ExportFormat magcal_format();
ExportFormat imu_tk_format();
ExportFormat kalibr_format();
ExportFormat px4_format();
ExportFormat ardupilot_format();
ExportFormat c_format();

}  // namespace scalcal
