// Text checks the tests share: whether a message holds a phrase (the tests check error and report texts by
// the phrases a user reads, not by whole strings that would break on every rewording).
#pragma once

#include <string>

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
