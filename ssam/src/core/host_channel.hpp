// SPDX-License-Identifier: MIT
#pragma once
// The boundary between a host API and its host: the message callback, the last message, and the
// exception boundary every public call runs inside (a Failure becomes its Status, anything else
// OutOfMemory or Internal, each with a message that starts with the API's name).
#include <exception>
#include <new>
#include <string>

#include "failure.hpp"

namespace ssam::core {

class HostChannel {
public:
    explicit HostChannel(const char* api) : api_(api) {}

    void setCallback(MessageCallback callback, void* user) noexcept { callback_ = callback, user_ = user; }
    const char* lastMessage() const noexcept { return last_.c_str(); }

    void message(Severity severity, const std::string& text) const noexcept {
        if (!callback_) return;
        try {
            callback_(user_, severity, text.c_str());
        } catch (...) {  // the host's callback must not unwind through SSAM
        }
    }

    // Keeps `text` as the last message, tells the callback, returns `status`.
    Status fail(Status status, const char* text) noexcept {
        try {
            last_ = text;
        } catch (...) {
            last_.clear();
        }
        message(Severity::Error, text);
        return status;
    }

    // Runs one public call: Ok, or the status of what it threw with its message; `onFailure` runs
    // first then (e.g. abandoning the open frame) and must not throw.
    template <class Body, class OnFailure>
    Status run(Body&& body, OnFailure&& onFailure) noexcept {
        try {
            body();
            return Status::Ok;
        } catch (const Failure& e) {
            onFailure();
            return fail(e.status, e.what());
        } catch (const std::bad_alloc&) {
            onFailure();
            return fail(Status::OutOfMemory, (api_ + ": out of memory").c_str());
        } catch (const std::exception& e) {
            onFailure();
            return fail(Status::Internal, (api_ + ": unexpected error: " + e.what()).c_str());
        } catch (...) {
            onFailure();
            return fail(Status::Internal, (api_ + ": unexpected error").c_str());
        }
    }

private:
    std::string api_;
    MessageCallback callback_ = nullptr;
    void* user_ = nullptr;
    std::string last_;
};

}  // namespace ssam::core
