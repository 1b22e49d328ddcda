#pragma once
#include <cstddef>

#include <nlohmann/json.hpp>

namespace game {

// A SAX handler that accepts every value and leaves parse_error to the derived class: for
// finding the first error of a document (with its byte offset) without building it.
template <typename JsonType>
struct JsonErrorOnlySax : nlohmann::json_sax<JsonType> {
  using Base = nlohmann::json_sax<JsonType>;
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(typename Base::number_integer_t) override { return true; }
  bool number_unsigned(typename Base::number_unsigned_t) override { return true; }
  bool number_float(typename Base::number_float_t, const typename Base::string_t&) override {
    return true;
  }
  bool string(typename Base::string_t&) override { return true; }
  bool binary(typename Base::binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(typename Base::string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
};

}  // namespace game
