// The grammar value lsystem{} makes, for the other ways to write one: lsystem.book (the book's notation) and
// lsystem.load (cpfg's .l files) build an options table and make the grammar through the same reader.
#pragma once

#include <lua.hpp>

#include "kernels/lsystem/book_text.h"

namespace selfsim::interp {

// Reads the lsystem{} options table at `index` and pushes the grammar (bind_lsystem.cpp); throws Error.
int push_lsystem(lua_State* L, int index);
// Pushes the lsystem{} options a book grammar gives, with those of the table at `table` (0: none) beside them
// (bind_lsystem_book.cpp); throws Error when both give one.
void push_book_options(lua_State* L, const lsystem::BookGrammar& b, int table);
// lsystem.book(text [, options]) (bind_lsystem_book.cpp).
int lsystem_book(lua_State* L);
// lsystem.load("tree.l" [, options]): cpfg's file (bind_lsystem_load.cpp).
int lsystem_load(lua_State* L);

}  // namespace selfsim::interp
