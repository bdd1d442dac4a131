// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "vv/report/ReportPatient.h"

namespace vv::report {
namespace {

TEST(ReportPatient, FormatsDicomValues) {
    ReportPatient p;
    EXPECT_EQ(displayName(p, "Doe^Jane^Marie^Dr."), "Dr. Doe, Jane Marie");
    EXPECT_EQ(displayName(p, "Doe^Jane"), "Doe, Jane");
    EXPECT_EQ(displayName(p, "Doe"), "Doe");
    EXPECT_EQ(displayDate(p, "19700131"), "1970-01-31");
    EXPECT_EQ(displayDate(p, "31.01.1970"), "31.01.1970");
    EXPECT_EQ(displayText(p, "  ACC-1 "), "ACC-1");
    EXPECT_EQ(displayText(p, ""), "\u2014");
    EXPECT_EQ(displayName(p, "^"), "\u2014");
}

TEST(ReportPatient, AnonymiseReplacesEveryField) {
    ReportPatient p;
    p.anonymise = true;
    EXPECT_EQ(displayName(p, "Doe^Jane"), "anonymised");
    EXPECT_EQ(displayDate(p, "19700131"), "anonymised");
    EXPECT_EQ(displayText(p, "12345"), "anonymised");
    EXPECT_EQ(displayText(p, ""), "anonymised");
}

}  // namespace
}  // namespace vv::report
