// SPDX-License-Identifier: GPL-3.0-or-later
// One form for a person's name wherever it is shown (vv/dicom/PersonName.h).
#include <gtest/gtest.h>

#include "vv/dicom/PersonName.h"

namespace {

using vv::dicom::personNameFromText;
using vv::dicom::personNameText;

TEST(PersonNameTest, ADicomNameReadsFamilyCommaGiven) {
    EXPECT_EQ(personNameText("Test^Large"), "Test, Large");
    EXPECT_EQ(personNameText("Doe^Jane^Marie^Dr.^Jr"), "Dr. Doe, Jane Marie, Jr");
    EXPECT_EQ(personNameText("Doe^Jane^Marie^Dr."), "Dr. Doe, Jane Marie");
    EXPECT_EQ(personNameText("Doe"), "Doe");
    EXPECT_EQ(personNameText("Doe^^^^"), "Doe");
    EXPECT_EQ(personNameText(" Doe ^ Jane "), "Doe, Jane");
    EXPECT_EQ(personNameText("^Jane"), "Jane");
    EXPECT_EQ(personNameText("Yamada^Tarou=山田^太郎"), "Yamada, Tarou");  // the alphabetic group
    EXPECT_EQ(personNameText(""), "");
    EXPECT_EQ(personNameText("^"), "");
}

TEST(PersonNameTest, ATypedNameBecomesADicomName) {
    EXPECT_EQ(personNameFromText("Doe, Jane"), "Doe^Jane");
    EXPECT_EQ(personNameFromText("  Doe ,  Jane Marie "), "Doe^Jane Marie");
    EXPECT_EQ(personNameFromText("Doe^Jane"), "Doe^Jane");
    EXPECT_EQ(personNameFromText("Doe"), "Doe");
    EXPECT_EQ(personNameFromText("Doe,"), "Doe");
    EXPECT_EQ(personNameFromText(""), "");
    // What is typed and what is shown agree.
    EXPECT_EQ(personNameText(personNameFromText("Test, Large")), "Test, Large");
}

}  // namespace
