// The writers of `scalcal export`'s targets (export_formats.cpp): each fills result.text (and the
// rotation or dropped share its form implies) from result.correction.
#pragma once
#include "commands/export.hpp"

namespace scalcal::commands {

void write_magcal(const ExportRequest& request, ExportResult& result);
void write_imu_tk(const ExportRequest& request, ExportResult& result);
void write_kalibr(const ExportRequest& request, ExportResult& result);
void write_px4(const ExportRequest& request, ExportResult& result);
void write_ardupilot(const ExportRequest& request, ExportResult& result);

}  // namespace scalcal::commands
