// A program embedding two machines generated with `smachac -target=cpp -emit=library`
// (counter.yml and light.yml): each library's build() makes its machine, rt::run runs it, and
// the outcome and userdata are printed. Both libraries define a class Step and a function
// stepAmount() (templates/Step.tpl.cpp) with different amounts: each machine must use its own.
#include <array>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <string>
#include <string_view>

#include "smachac-e2e-light.h"
#include "smachac_e2e_counter.h"

namespace rt = smachac::runtime;

namespace {

template <std::size_t N>
std::string joined(const std::array<std::string_view, N>& names) {
  std::string text;
  for (std::string_view name : names) text += (text.empty() ? "" : " ") + std::string(name);
  return text;
}

}  // namespace

int main() {
  std::unique_ptr<rt::StateMachine> counter = smachac_e2e_counter::build();
  rt::RunResult counted = rt::run(*counter);
  std::cout << "counter: " << counted.outcome << ", n = " << counter->userdata().get<int64_t>("n")
            << " (outcomes: " << joined(smachac_e2e_counter::outcomes)
            << "; userdata: " << joined(smachac_e2e_counter::userdata_keys) << ")\n";

  std::unique_ptr<rt::StateMachine> light = smachac_e2e_light::build();
  rt::RunResult lit = rt::run(*light);
  std::cout << "light: " << lit.outcome << ", n = " << light->userdata().get<int64_t>("n")
            << ", colour = " << light->userdata().get<std::string>("colour")
            << " (outcomes: " << joined(smachac_e2e_light::outcomes) << ")\n";

  std::unique_ptr<rt::StateMachine> again = smachac_e2e_counter::build();
  std::cout << "a new counter: n = " << again->userdata().get<int64_t>("n") << "\n";
  for (const rt::RunResult* result : {&counted, &lit}) {
    if (!result->ok()) std::cout << "error: " << result->error << "\n";
  }
  return counted.ok() && lit.ok() ? 0 : 1;
}
