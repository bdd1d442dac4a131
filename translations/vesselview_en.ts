<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>vv::app::SegmentationText</name>
    <message numerus="yes">
        <source>the %n largest</source>
        <translation>
            <numerusform>the largest</numerusform>
            <numerusform>the %n largest</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n more such end(s).</source>
        <translation>
            <numerusform>%n more such end.</numerusform>
            <numerusform>%n more such ends.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vv::gui::DocumentController</name>
    <message numerus="yes">
        <source>%1: no DICOM images found (%n file(s) skipped)</source>
        <translation>
            <numerusform>%1: no DICOM images found (%n file skipped)</numerusform>
            <numerusform>%1: no DICOM images found (%n files skipped)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vv::gui::MainWindow</name>
    <message numerus="yes">
        <source>%n files</source>
        <translation>
            <numerusform>%n file</numerusform>
            <numerusform>%n files</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vv::gui::MeshLoadTask</name>
    <message numerus="yes">
        <source>Loading %n file(s)</source>
        <translation>
            <numerusform>Loading %n file</numerusform>
            <numerusform>Loading %n files</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vv::gui::NetworkFailure</name>
    <message numerus="yes">
        <source>after %n image(s)</source>
        <translation>
            <numerusform>after %n image</numerusform>
            <numerusform>after %n images</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n image(s) of it were kept in the local study store.</source>
        <translation>
            <numerusform>%n image of it was kept in the local study store.</numerusform>
            <numerusform>%n images of it were kept in the local study store.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vv::gui::StudyRunDialog</name>
    <message numerus="yes">
        <source>%n scene(s)</source>
        <translation>
            <numerusform>%n scene</numerusform>
            <numerusform>%n scenes</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vv::report::ReportText</name>
    <message numerus="yes">
        <source>%n answer(s) repeated a stimulus already answered (a resumed run): only the first counts.</source>
        <translation>
            <numerusform>%n answer repeated a stimulus already answered (a resumed run): only the first counts.</numerusform>
            <numerusform>%n answers repeated a stimulus already answered (a resumed run): only the first counts.</numerusform>
        </translation>
    </message>
</context>
</TS>
