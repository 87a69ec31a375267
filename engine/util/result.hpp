#pragma once
// Errors that come from outside (files, parameters, devices) are values: a Result holds
// either the value or one clear message naming the file, line or field that is wrong.
// Bugs inside the program are assertions, not Results.

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace gem {

struct Error {
    std::string message;
};

template <class T>
class [[nodiscard]] Result {
  public:
    Result(T value) : state_(std::move(value)) {}
    Result(Error error) : state_(std::move(error)) {}

    bool ok() const { return state_.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & {
        assert(ok());
        return std::get<0>(state_);
    }
    const T& value() const& {
        assert(ok());
        return std::get<0>(state_);
    }
    T&& value() && {
        assert(ok());
        return std::get<0>(std::move(state_));
    }
    const std::string& error() const {
        assert(!ok());
        return std::get<1>(state_).message;
    }

  private:
    std::variant<T, Error> state_;
};

}  // namespace gem
