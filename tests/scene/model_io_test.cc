// Copyright contactlaws authors.
//
// Loading MJCF scenes: the MuJoCo version, errors that name the file and line.

#include "contactlaws/contact_model.h"

#include <string>

#include <gtest/gtest.h>


namespace contactlaws {
namespace {

TEST(ModelIoTest, MujocoIsTwoTwoTwo) { EXPECT_EQ(MujocoVersion(), 222); }

TEST(ModelIoTest, MalformedXmlNamesTheFileAndLine) {
  try {
    LoadModelString("<mujoco>\n<worldbody>\n<geom type=\"sphere\" size=\"0.1\">\n</mujoco>", "broken.xml");
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("broken.xml: ", 0), 0u) << message;
    EXPECT_NE(message.find("Line number=3"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
  }
}

}  // namespace
}  // namespace contactlaws
