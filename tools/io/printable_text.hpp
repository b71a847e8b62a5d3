#pragma once
// Text for a terminal, from text that quotes what a user's file holds (a capture's field, a file
// name): a message must stay one line and must not carry bytes a terminal would act on or show as
// garbage. Valid UTF-8 is kept (messages and names use it: "→", "°", a Chinese file name); a
// newline or carriage return becomes \n or \r, and every other control character (C0, DEL, and
// the C1 range U+0080–U+009F, which some terminals read as escape sequences) and every byte that
// is not part of a valid UTF-8 sequence (a Latin-1 "é" is 0xE9) becomes \xNN. Overlong forms,
// surrogates and code points past U+10FFFF are not valid UTF-8 (RFC 3629 §3).
#include <string>
#include <string_view>

namespace stoneskip {

std::string printable_text(std::string_view bytes);

}  // namespace stoneskip
