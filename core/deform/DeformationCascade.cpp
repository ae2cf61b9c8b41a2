#include "core/deform/DeformationCascade.h"

#include "core/common/Error.h"
#include "core/common/TextParsing.h"

#include <cmath>
#include <set>

namespace vl {

int DeformationCascade::findParameter(std::string_view parameterName) const {
    for (std::size_t k = 0; k < parameters.size(); ++k)
        if (parameters[k].name == parameterName) return static_cast<int>(k);
    return -1;
}

std::vector<double> DeformationCascade::defaults() const {
    std::vector<double> q;
    q.reserve(parameters.size());
    for (const auto& p : parameters) q.push_back(p.defaultValue);
    return q;
}

Vec3 DeformationCascade::evaluate(double u, double v, std::span<const double> q) const {
    checkParameterValues(*this, q);
    return evaluateUnchecked(u, v, q);
}

Vec3 DeformationCascade::evaluateUnchecked(double u, double v, std::span<const double> q) const {
    Vec3 p(0.0, 0.0, 0.0);
    for (const auto& stage : stages) {
        if (stage.kind == StageKind::Constant)
            p = stage.field.at(u, v);
        else if (q[stage.parameter] != 0.0)
            p += q[stage.parameter] * stage.field.at(u, v);
    }
    return p;
}

namespace {

std::string cascadeWhere(const DeformationCascade& cascade) {
    return "deformation cascade '" + cascade.name + "'";
}

std::string rangeText(const DeformParameter& p) {
    return "[" + formatDouble(p.min) + ", " + formatDouble(p.max) + "]";
}

} // namespace

void validateCascade(const DeformationCascade& cascade) {
    const std::string where = cascadeWhere(cascade);
    std::set<std::string, std::less<>> names;
    for (std::size_t k = 0; k < cascade.parameters.size(); ++k) {
        const auto& p = cascade.parameters[k];
        const std::string at = where + ": parameter " + std::to_string(k) + " '" + p.name + "'";
        if (p.name.empty()) throwInputError(at, "has an empty name");
        if (!names.insert(p.name).second) throwInputError(at, "repeats a name");
        if (!std::isfinite(p.min) || !std::isfinite(p.max) || !std::isfinite(p.defaultValue))
            throwInputError(at, "has a value that is not finite");
        if (p.min > p.max) throwInputError(at, "has min > max in " + rangeText(p));
        if (p.defaultValue < p.min || p.defaultValue > p.max)
            throwInputError(at, "default " + formatDouble(p.defaultValue) + " is outside " + rangeText(p));
    }
    if (cascade.stages.empty() || cascade.stages.front().kind != StageKind::Constant)
        throwInputError(where, "the first stage must be a Constant stage (the base geometry)");
    for (std::size_t k = 0; k < cascade.stages.size(); ++k) {
        const auto& stage = cascade.stages[k];
        const std::string at = where + ": stage " + std::to_string(k) + " '" + stage.name + "'";
        if (stage.kind == StageKind::AddVector && stage.parameter >= cascade.parameters.size())
            throwInputError(at, "uses parameter index " + std::to_string(stage.parameter) +
                                    " but there are " + std::to_string(cascade.parameters.size()) +
                                    " parameters");
        validateField(stage.field, at);
    }
}

void checkParameterValues(const DeformationCascade& cascade, std::span<const double> q) {
    if (q.size() != cascade.parameters.size())
        throwInputError(cascadeWhere(cascade), "got " + std::to_string(q.size()) +
                                                   " parameter values, expected " +
                                                   std::to_string(cascade.parameters.size()));
    for (std::size_t k = 0; k < q.size(); ++k) {
        const auto& p = cascade.parameters[k];
        if (!(q[k] >= p.min && q[k] <= p.max)) // also rejects NaN
            throwInputError("parameter '" + p.name + "'",
                            "value " + formatDouble(q[k]) + " is outside " + rangeText(p));
    }
}

DeformationCascade retarget(const DeformationCascade& cascade, const VectorField& base, std::string name) {
    DeformationCascade result = cascade;
    result.name = std::move(name);
    for (auto& stage : result.stages)
        if (stage.kind == StageKind::Constant) stage.field = base;
    return result;
}

} // namespace vl
