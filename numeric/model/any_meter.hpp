// The meter of any registered model as one value (a fit's estimate, a simulation's truth): the registered models'
// meter types, each once, in a variant. A model that brings a new meter type adds it here by its registration line.
#pragma once
#include <type_traits>
#include <utility>
#include <variant>

#include <Eigen/Core>

#include "numeric/model/registry.hpp"

namespace scalcal {

namespace detail {
// The distinct `meter` types of a list of models, in the order they first appear, as a std::variant.
template <class Found, class... Models>
struct distinct_meters;
template <class... Found>
struct distinct_meters<TypeList<Found...>> {
  using type = std::variant<Found...>;
};
template <class... Found, class M, class... Rest>
struct distinct_meters<TypeList<Found...>, M, Rest...> {
  using type = typename std::conditional_t<(std::is_same_v<typename M::meter, Found> || ...),
                                           distinct_meters<TypeList<Found...>, Rest...>,
                                           distinct_meters<TypeList<Found..., typename M::meter>, Rest...>>::type;
};
template <class... Models>
auto meter_variant(TypeList<Models...>) -> typename distinct_meters<TypeList<>, Models...>::type;
}  // namespace detail

class AnyMeter {
 public:
  AnyMeter() = default;  // the first registered model's meter, all parameters zero
  template <CalibrationMeter M>
  AnyMeter(M meter) : meter_(std::move(meter)) {}  // implicit: every model's meter is one

  Vec3 measure(const Vec3& I) const {
    return std::visit([&](const auto& m) { return m.measure(I); }, meter_);
  }
  Vec3 compensate(const Vec3& measured) const {
    return std::visit([&](const auto& m) { return m.compensate(measured); }, meter_);
  }
  // Its part of eq. (2): bias, scale factors, misalignment.
  const Meter& linear() const {
    return std::visit([](const auto& m) -> const Meter& { return m.linear; }, meter_);
  }
  // The meter's own parameters (its type's kParameters order) in the estimator's units.
  Eigen::VectorXd parameters(double magnitude) const {
    return std::visit([&](const auto& m) { return Eigen::VectorXd(m.parameters(magnitude)); }, meter_);
  }
  // The meter as its type, or null when it is another.
  template <CalibrationMeter M>
  const M* as() const {
    return std::get_if<M>(&meter_);
  }
  template <CalibrationMeter M>
  M* as() {
    return std::get_if<M>(&meter_);
  }

 private:
  decltype(detail::meter_variant(RegisteredModels{})) meter_;
};

}  // namespace scalcal
