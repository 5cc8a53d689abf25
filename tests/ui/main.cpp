// The editor's tests run offscreen (no display needed) in one QApplication, with settings of
// their own: a fresh, private directory per test process, so that tests running side by side
// (ctest -j) or a user's own settings and autosaved work never leak into a test.
#include <gtest/gtest.h>

#include <QApplication>
#include <QTemporaryDir>

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QTemporaryDir config;
  qputenv("XDG_CONFIG_HOME", config.path().toLocal8Bit());
  // The autosaved copies too (document/autosave.h).
  qputenv("XDG_DATA_HOME", (config.path() + "/data").toLocal8Bit());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("linkage-tests");
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
