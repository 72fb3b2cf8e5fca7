#pragma once
// Builds one std::visit visitor from several lambdas.

namespace bridge {

template <typename... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <typename... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

}  // namespace bridge
