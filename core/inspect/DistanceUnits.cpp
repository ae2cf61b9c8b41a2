#include "core/inspect/DistanceUnits.h"

#include <algorithm>
#include <cmath>

namespace vl {

double rmsDistance(double cost, double frequencySum, double weightSum) {
    if (!(frequencySum > 0.0) || !(weightSum > 0.0) || !(cost > 0.0)) return 0.0;
    return std::sqrt(cost / (frequencySum * weightSum));
}

LengthUnit guessLengthUnit(double extent) {
    for (const LengthUnit unit :
         {LengthUnit::Metre, LengthUnit::Centimetre, LengthUnit::Millimetre, LengthUnit::Inch}) {
        const double metres = extent * millimetresPer(unit) / 1000.0;
        if (metres >= 0.05 && metres <= 1.0) return unit;
    }
    return LengthUnit::Metre;
}

double millimetresPer(LengthUnit unit) {
    switch (unit) {
    case LengthUnit::Metre:
        return 1000.0;
    case LengthUnit::Centimetre:
        return 10.0;
    case LengthUnit::Millimetre:
        return 1.0;
    case LengthUnit::Inch:
        return 25.4;
    }
    return 1.0;
}

const char* lengthUnitName(LengthUnit unit) {
    switch (unit) {
    case LengthUnit::Metre:
        return "m";
    case LengthUnit::Centimetre:
        return "cm";
    case LengthUnit::Millimetre:
        return "mm";
    case LengthUnit::Inch:
        return "in";
    }
    return "";
}

int axisTicks(double lo, double hi, int count, bool logarithmic, double* ticks, int capacity) {
    if (!(hi >= lo) || !std::isfinite(lo) || !std::isfinite(hi) || capacity <= 0 || count < 1) return 0;
    int written = 0;
    if (logarithmic && lo > 0.0) {
        // The powers of ten in range; over more decades than `count` allows, every k-th one
        // (exponents divisible by k), so the labels keep their room.
        const int first = static_cast<int>(std::ceil(std::log10(lo) - 1e-9));
        const int last = static_cast<int>(std::floor(std::log10(hi) + 1e-9));
        const int step = std::max(1, (last - first + count - 1) / count);
        for (int e = first; e <= last && written < capacity; ++e)
            if (e % step == 0) ticks[written++] = std::pow(10.0, e);
        if (written >= 2) return written;
        written = 0; // less than a decade: fall through to linear steps
    }
    const double span = hi > lo ? hi - lo : std::max(std::abs(hi), 1.0);
    const double raw = span / count;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (const double factor : {1.0, 2.0, 5.0, 10.0})
        if (factor * magnitude >= raw) {
            step = factor * magnitude;
            break;
        }
    for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * span && written < capacity;
         t += step)
        ticks[written++] = std::abs(t) < 1e-12 * step ? 0.0 : t;
    return written;
}

double guessMillimetresPerUnit(std::span<const Vec3> positions) {
    Vec3 lo, hi;
    if (!bounds(positions, lo, hi)) return millimetresPer(LengthUnit::Metre);
    return millimetresPer(guessLengthUnit(std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]})));
}

} // namespace vl
