#include "contactlaws/law.h"
#include <gtest/gtest.h>
TEST(Law, Placeholder) { EXPECT_EQ(contactlaws::LawName(contactlaws::LawKind::kFlores), "flores"); }
