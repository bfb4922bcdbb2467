// The rehearsal of a tumbling log (simulate --log --tumble SECONDS): a meter turned continuously,
// never resting, at 60 degrees per second along great circles through the program's positions
// (repeated) or, without a program, through random directions from the seed. A magnetometer's field
// keeps its modulus however the meter turns; an accelerometer's specific force adds the motion's
// acceleration (smooth, 5 % of |I| RMS: hand motion), which is what calibrate must refuse to fit as
// if it were still. Disturbed stretches (a magnet passing): 2 s each, a field of up to 0.3 |I| rising
// and falling, at random times; the truth file lists them.
#pragma once
#include "commands/calibration/rehearsal.hpp"

namespace scalcal::commands {

inline constexpr double kTumbleDegPerS = 60;       // the turning speed
inline constexpr double kHandAcceleration = 0.05;  // the accelerometer's motion, RMS, |I|
inline constexpr double kDisturbanceField = 0.3;   // a disturbance's peak, |I|
inline constexpr double kDisturbanceSeconds = 2;

RehearsalResult rehearse_tumbling(const RehearsalRequest& request);

}  // namespace scalcal::commands
