// SPDX-License-Identifier: GPL-3.0-or-later
// The GUI's translations (translations/*.ts): German complete and finished,
// placeholders and mnemonics kept, English plural forms given, no string in
// app/gui or app/common that the .ts files lack (lupdate run into a temporary file), and
// the compiled .qm translating at run time. No display, no network.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <QTranslator>
#include <QXmlStreamReader>
#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Message {
    QString context;
    QString source;
    bool numerus = false;
    bool obsolete = false;    ///< type vanished / obsolete: no longer in the sources
    bool unfinished = false;  ///< type unfinished
    QString translation;      ///< the translation (not numerus)
    QStringList forms;        ///< numerus forms
};

/// Parses a Qt Linguist .ts file; adds a test failure when it is not valid XML.
std::vector<Message> readTs(const QString& path) {
    std::vector<Message> messages;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        ADD_FAILURE() << "cannot open " << path.toStdString();
        return messages;
    }
    QXmlStreamReader xml(&file);
    QString context;
    Message message;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            const auto name = xml.name();
            if (name == QLatin1String("context")) {
                context.clear();
            } else if (name == QLatin1String("name")) {
                context = xml.readElementText();
            } else if (name == QLatin1String("message")) {
                message = Message{};
                message.context = context;
                message.numerus =
                    xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
            } else if (name == QLatin1String("source")) {
                message.source = xml.readElementText();
            } else if (name == QLatin1String("translation")) {
                const auto type = xml.attributes().value(QLatin1String("type"));
                message.obsolete =
                    type == QLatin1String("vanished") || type == QLatin1String("obsolete");
                message.unfinished = type == QLatin1String("unfinished");
                if (!message.numerus) {
                    message.translation = xml.readElementText();
                }
            } else if (name == QLatin1String("numerusform")) {
                message.forms << xml.readElementText();
            }
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            messages.push_back(message);
        }
    }
    if (xml.hasError()) {
        ADD_FAILURE() << path.toStdString() << ": " << xml.errorString().toStdString()
                      << " at line " << xml.lineNumber();
    }
    return messages;
}

QString tsPath(const char* language) {
    return QStringLiteral(VV_SOURCE_DIR "/translations/vesselview_%1.ts")
        .arg(QLatin1String(language));
}

std::string describe(const Message& m) {
    return m.context.toStdString() + " / \"" + m.source.toStdString() + "\"";
}

/// The placeholders (%1 … %99, %n, %L1) of `text`, sorted.
QStringList placeholders(const QString& text) {
    static const QRegularExpression re(QStringLiteral("%L?(\\d{1,2}|n)"));
    QStringList found;
    for (auto it = re.globalMatch(text); it.hasNext();) {
        found << it.next().captured(0);
    }
    found.sort();
    return found;
}

/// How many mnemonic ampersands ("&x", not "&&") `text` holds.
int mnemonics(const QString& text) {
    int count = 0;
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text[i] == QLatin1Char('&')) {
            if (text[i + 1] == QLatin1Char('&')) {
                ++i;
            } else if (!text[i + 1].isSpace()) {
                ++count;
            }
        }
    }
    return count;
}

TEST(Translations, GermanIsCompleteAndFinished) {
    const auto messages = readTs(tsPath("de"));
    ASSERT_GT(messages.size(), 100U) << "suspiciously few strings in vesselview_de.ts";
    for (const Message& m : messages) {
        if (m.obsolete) {
            ADD_FAILURE() << "obsolete entry (run the vv_update_translations target): "
                          << describe(m);
            continue;
        }
        EXPECT_FALSE(m.unfinished) << "unfinished German translation: " << describe(m);
        if (m.numerus) {
            ASSERT_EQ(m.forms.size(), 2) << "German has two plural forms: " << describe(m);
            for (const QString& form : m.forms) {
                EXPECT_FALSE(form.trimmed().isEmpty()) << "empty plural form: " << describe(m);
                EXPECT_TRUE(form.contains(QLatin1String("%n"))) << describe(m);
            }
            continue;
        }
        EXPECT_FALSE(m.translation.trimmed().isEmpty())
            << "missing German translation: " << describe(m);
        EXPECT_EQ(placeholders(m.translation), placeholders(m.source))
            << "placeholders differ: " << describe(m) << " -> " << m.translation.toStdString();
        EXPECT_EQ(mnemonics(m.translation), mnemonics(m.source))
            << "mnemonic (&) lost or added: " << describe(m) << " -> "
            << m.translation.toStdString();
        EXPECT_EQ(m.translation.startsWith(QLatin1Char(' ')), m.source.startsWith(QLatin1Char(' ')))
            << "leading space differs: " << describe(m);
    }
}

TEST(Translations, EnglishPluralFormsAreGiven) {
    const auto messages = readTs(tsPath("en"));
    for (const Message& m : messages) {
        EXPECT_TRUE(m.numerus) << "vesselview_en.ts holds plural forms only: " << describe(m);
        EXPECT_FALSE(m.unfinished) << describe(m);
        ASSERT_EQ(m.forms.size(), 2) << describe(m);
        for (const QString& form : m.forms) {
            EXPECT_FALSE(form.trimmed().isEmpty()) << describe(m);
        }
    }
}

TEST(Translations, EveryStringInTheSourcesIsInTheTsFiles) {
    // lupdate over app/ and the modules that draw text (render, report) into a
    // temporary file: the strings the sources have now.
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString fresh = dir.filePath(QStringLiteral("fresh_de.ts"));
    QProcess lupdate;
    lupdate.setProcessChannelMode(QProcess::MergedChannels);
    lupdate.start(
        QStringLiteral(VV_LUPDATE),
        {QStringLiteral("-silent"), QStringLiteral("-locations"), QStringLiteral("none"),
         QStringLiteral("-I"), QStringLiteral(VV_SOURCE_DIR "/app"),
         QStringLiteral("-source-language"), QStringLiteral("en"),
         QStringLiteral("-target-language"), QStringLiteral("de"),
         QStringLiteral(VV_SOURCE_DIR "/app/gui"), QStringLiteral(VV_SOURCE_DIR "/app/common"),
         QStringLiteral(VV_SOURCE_DIR "/app/cli"),
         QStringLiteral(VV_SOURCE_DIR "/modules/render/src"),
         QStringLiteral(VV_SOURCE_DIR "/modules/report/src"), QStringLiteral("-ts"), fresh});
    ASSERT_TRUE(lupdate.waitForFinished(120000)) << "lupdate did not finish";
    ASSERT_EQ(lupdate.exitCode(), 0) << lupdate.readAll().toStdString();

    const auto current = readTs(fresh);
    ASSERT_GT(current.size(), 100U) << "lupdate found too few strings";
    std::set<std::pair<QString, QString>> german;
    std::set<std::pair<QString, QString>> english;
    for (const Message& m : readTs(tsPath("de"))) {
        german.emplace(m.context, m.source);
    }
    for (const Message& m : readTs(tsPath("en"))) {
        english.emplace(m.context, m.source);
    }
    std::set<std::pair<QString, QString>> inSources;
    for (const Message& m : current) {
        inSources.emplace(m.context, m.source);
        EXPECT_TRUE(german.count({m.context, m.source}) == 1)
            << "new string without German translation (build the vv_update_translations "
               "target, then translate it in translations/vesselview_de.ts): "
            << describe(m);
        if (m.numerus) {
            EXPECT_TRUE(english.count({m.context, m.source}) == 1)
                << "plural string without English forms in vesselview_en.ts: " << describe(m);
        }
    }
    for (const auto& [context, source] : german) {
        EXPECT_TRUE(inSources.count({context, source}) == 1)
            << "vesselview_de.ts holds a string the sources no longer have (run the "
               "vv_update_translations target): "
            << context.toStdString() << " / \"" << source.toStdString() << "\"";
    }
}

TEST(Translations, CompiledGermanTranslatesAtRunTime) {
    QTranslator translator;
    ASSERT_TRUE(translator.load(QStringLiteral("vesselview_de"), QStringLiteral(VV_QM_DIR)))
        << "no vesselview_de.qm in " VV_QM_DIR;
    EXPECT_EQ(translator.translate("vv::gui::MainWindow", "&File"), QStringLiteral("&Datei"));
    EXPECT_EQ(translator.translate("vv::gui::panels::EngineNames", "Dark means deep"),
              QStringLiteral("Dunkel bedeutet tief"));
    EXPECT_EQ(translator.translate("vv::gui::MainWindow", "%n files", nullptr, 3),
              QStringLiteral("%n Dateien"));
    EXPECT_EQ(translator.translate("vv::gui::MainWindow", "%n files", nullptr, 1),
              QStringLiteral("%n Datei"));

    QTranslator english;
    ASSERT_TRUE(english.load(QStringLiteral("vesselview_en"), QStringLiteral(VV_QM_DIR)));
    EXPECT_EQ(english.translate("vv::gui::MainWindow", "%n files", nullptr, 1),
              QStringLiteral("%n file"));
}

}  // namespace
