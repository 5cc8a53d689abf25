// The editor's tests run offscreen (no display needed) in one QApplication.
#include <gtest/gtest.h>

#include <QApplication>

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  QApplication::setOrganizationName("linkage-tests");  // settings apart from a user's
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
