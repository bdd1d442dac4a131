<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>main</name>
    <message>
        <source>Vessel tree workstation. Opens the given mesh files, or the demo.</source>
        <translation>Arbeitsplatz für Gefäßbäume. Öffnet die angegebenen Netzdateien oder die Demo.</translation>
    </message>
    <message>
        <source>Save the first frame with the data to &lt;png&gt; and quit.</source>
        <translation>Das erste Bild mit den Daten als &lt;png&gt; speichern und beenden.</translation>
    </message>
    <message>
        <source>User interface language, e.g. en or de (default: the system&apos;s).</source>
        <translation>Sprache der Benutzeroberfläche, z. B. en oder de (Standard: die des Systems).</translation>
    </message>
    <message>
        <source>Mesh files (STL, OBJ, PLY, VTK, VTP, VTU), or one session file (.vvs).</source>
        <translation>Netzdateien (STL, OBJ, PLY, VTK, VTP, VTU) oder eine Sitzungsdatei (.vvs).</translation>
    </message>
</context>
<context>
    <name>vv::app::MeasurementText</name>
    <message>
        <source>Landmarks</source>
        <translation>Landmarken</translation>
    </message>
    <message>
        <source>Landmark</source>
        <translation>Landmarke</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <source>the section there has no closed lumen contour</source>
        <translation>der Querschnitt dort hat keine geschlossene Lumenkontur</translation>
    </message>
    <message>
        <source>* Where lumens merge: the section holds part of the other lumen.</source>
        <translation>* Wo Lumina zusammenlaufen: der Querschnitt enthält einen Teil des anderen Lumens.</translation>
    </message>
    <message>
        <source>Lengths between landmarks</source>
        <translation>Längen zwischen Landmarken</translation>
    </message>
    <message>
        <source>From – to</source>
        <translation>Von – bis</translation>
    </message>
    <message>
        <source>Along the centreline</source>
        <translation>Entlang der Mittellinie</translation>
    </message>
    <message>
        <source>Straight</source>
        <translation>Gerade</translation>
    </message>
    <message>
        <source>Aortic sizing: diameters</source>
        <translation>Aortale Vermessung: Durchmesser</translation>
    </message>
    <message>
        <source>Place</source>
        <translation>Ort</translation>
    </message>
    <message>
        <source>Neck at the lowest renal artery</source>
        <translation>Hals an der untersten Nierenarterie</translation>
    </message>
    <message>
        <source>Neck %1 mm below the lowest renal artery</source>
        <translation>Hals %1 mm unterhalb der untersten Nierenarterie</translation>
    </message>
    <message>
        <source>Largest aneurysm diameter</source>
        <translation>Größter Aneurysmadurchmesser</translation>
    </message>
    <message>
        <source>Smallest left iliac (access)</source>
        <translation>Kleinster Durchmesser links iliakal (Zugang)</translation>
    </message>
    <message>
        <source>Smallest right iliac (access)</source>
        <translation>Kleinster Durchmesser rechts iliakal (Zugang)</translation>
    </message>
    <message>
        <source>Below: along the centreline from the tree&apos;s source towards the aortic bifurcation. Smallest iliac: the section of smallest minimum diameter from the aortic bifurcation to the internal iliac origin.</source>
        <translation>Unterhalb: entlang der Mittellinie vom Ursprung des Baums zur Aortenbifurkation hin. Kleinster iliakaler Durchmesser: der Querschnitt mit dem kleinsten minimalen Durchmesser von der Aortenbifurkation bis zum Abgang der A. iliaca interna.</translation>
    </message>
    <message>
        <source>Aortic sizing: lengths and angles</source>
        <translation>Aortale Vermessung: Längen und Winkel</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Maß</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Neck length (lowest renal artery to start of the aneurysm)</source>
        <translation>Halslänge (unterste Nierenarterie bis Beginn des Aneurysmas)</translation>
    </message>
    <message>
        <source>Angle α (suprarenal aorta to neck)</source>
        <translation>Winkel α (suprarenale Aorta zum Hals)</translation>
    </message>
    <message>
        <source>Angle β (neck to aneurysm)</source>
        <translation>Winkel β (Hals zum Aneurysma)</translation>
    </message>
    <message>
        <source>Lowest renal artery to aortic bifurcation</source>
        <translation>Unterste Nierenarterie bis Aortenbifurkation</translation>
    </message>
    <message>
        <source>Lowest renal artery to left internal iliac origin</source>
        <translation>Unterste Nierenarterie bis Abgang der A. iliaca interna links</translation>
    </message>
    <message>
        <source>Lowest renal artery to right internal iliac origin</source>
        <translation>Unterste Nierenarterie bis Abgang der A. iliaca interna rechts</translation>
    </message>
    <message>
        <source>Aortic bifurcation to left internal iliac origin</source>
        <translation>Aortenbifurkation bis Abgang der A. iliaca interna links</translation>
    </message>
    <message>
        <source>Aortic bifurcation to right internal iliac origin</source>
        <translation>Aortenbifurkation bis Abgang der A. iliaca interna rechts</translation>
    </message>
    <message>
        <source>Angles between the principal axes of the centreline: the suprarenal aorta over 15 mm above the lowest renal artery, the neck, and the aneurysm from its start to the aortic bifurcation.</source>
        <translation>Winkel zwischen den Hauptachsen der Mittellinie: die suprarenale Aorta über 15 mm oberhalb der untersten Nierenarterie, der Hals und das Aneurysma von seinem Beginn bis zur Aortenbifurkation.</translation>
    </message>
    <message>
        <source>Branches</source>
        <translation>Äste</translation>
    </message>
    <message>
        <source>Branch</source>
        <translation>Ast</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Narrowest</source>
        <translation>Engste Stelle</translation>
    </message>
    <message>
        <source>Widest</source>
        <translation>Weiteste Stelle</translation>
    </message>
    <message>
        <source>Stenosis (diameter)</source>
        <translation>Stenose (Durchmesser)</translation>
    </message>
    <message>
        <source>Branch %1</source>
        <translation>Ast %1</translation>
    </message>
    <message>
        <source>Narrowest and widest: equivalent diameters outside the branch&apos;s ends and junctions; stenosis at the narrowest point against the reference diameter.</source>
        <translation>Engste und weiteste Stelle: äquivalente Durchmesser außerhalb der Enden und Verzweigungen des Asts; Stenose an der engsten Stelle gegenüber dem Referenzdurchmesser.</translation>
    </message>
    <message>
        <source>Lowest renal artery</source>
        <translation>Unterste Nierenarterie</translation>
    </message>
    <message>
        <source>Start of the aneurysm</source>
        <translation>Beginn des Aneurysmas</translation>
    </message>
    <message>
        <source>Aortic bifurcation</source>
        <translation>Aortenbifurkation</translation>
    </message>
    <message>
        <source>Left internal iliac origin</source>
        <translation>Abgang der A. iliaca interna links</translation>
    </message>
    <message>
        <source>Right internal iliac origin</source>
        <translation>Abgang der A. iliaca interna rechts</translation>
    </message>
    <message>
        <source>no landmark “%1” is placed</source>
        <translation>keine Landmarke „%1“ gesetzt</translation>
    </message>
    <message>
        <source>no landmark below the neck sets the aortic path</source>
        <translation>keine Landmarke unterhalb des Halses legt den aortalen Pfad fest</translation>
    </message>
    <message>
        <source>“%1” is not on the centreline from the source to “%2”</source>
        <translation>„%1“ liegt nicht auf der Mittellinie vom Ursprung bis „%2“</translation>
    </message>
    <message>
        <source>the aortic path ends less than %1 mm below the lowest renal artery</source>
        <translation>der aortale Pfad endet weniger als %1 mm unterhalb der untersten Nierenarterie</translation>
    </message>
    <message>
        <source>the start of the aneurysm is not below the lowest renal artery</source>
        <translation>der Beginn des Aneurysmas liegt nicht unterhalb der untersten Nierenarterie</translation>
    </message>
    <message>
        <source>the neck is shorter than %1 mm</source>
        <translation>der Hals ist kürzer als %1 mm</translation>
    </message>
    <message>
        <source>less than %1 mm of centreline above the lowest renal artery</source>
        <translation>weniger als %1 mm Mittellinie oberhalb der untersten Nierenarterie</translation>
    </message>
    <message>
        <source>the aneurysm is shorter than %1 mm</source>
        <translation>das Aneurysma ist kürzer als %1 mm</translation>
    </message>
    <message>
        <source>no section between “%1” and “%2” measures the vessel itself</source>
        <translation>kein Querschnitt zwischen „%1“ und „%2“ misst das Gefäß selbst</translation>
    </message>
    <message>
        <source>not graded: too few sections measure the branch, or it has no healthy reference</source>
        <translation>nicht bewertet: zu wenige Querschnitte messen den Ast, oder er hat keine gesunde Referenz</translation>
    </message>
    <message>
        <source>Minimum %1, maximum %2, equivalent %3</source>
        <translation>Minimum %1, Maximum %2, Äquivalent %3</translation>
    </message>
    <message>
        <source>Diameter profile along the path (%1 long)</source>
        <translation>Durchmesserprofil entlang des Pfads (%1 lang)</translation>
    </message>
    <message>
        <source>Solid: equivalent diameter; dashed: minimum and maximum caliper diameter. Gaps: no section measures the vessel there (an end, a junction). Marked: narrowings of %1 or more in diameter.</source>
        <translation>Durchgezogen: Äquivalentdurchmesser; gestrichelt: minimaler und maximaler Messschieberdurchmesser. Lücken: Dort misst kein Schnitt das Gefäß (ein Ende, eine Verzweigung). Markiert: Einengungen ab %1 im Durchmesser.</translation>
    </message>
    <message>
        <source>Distance along the path (mm)</source>
        <translation>Abstand entlang des Pfads (mm)</translation>
    </message>
    <message>
        <source>Diameter (mm)</source>
        <translation>Durchmesser (mm)</translation>
    </message>
    <message>
        <source>Equivalent</source>
        <translation>Äquivalent</translation>
    </message>
    <message>
        <source>Minimum</source>
        <translation>Minimum</translation>
    </message>
    <message>
        <source>Maximum</source>
        <translation>Maximum</translation>
    </message>
    <message>
        <source>Ø: diameter. Equivalent Ø: 2√(area/π) of the lumen section perpendicular to the centreline; minimum and maximum Ø: its smallest and largest caliper (Feret) width. Lengths along the centreline unless marked straight.</source>
        <translation>Ø: Durchmesser. Äquivalenter Ø: 2√(Fläche/π) des Lumenquerschnitts senkrecht zur Mittellinie; minimaler und maximaler Ø: seine kleinste und größte Messschieber-(Feret-)Breite. Längen entlang der Mittellinie, sofern nicht als gerade bezeichnet.</translation>
    </message>
    <message>
        <source>Equivalent Ø</source>
        <translation>Äquivalenter Ø</translation>
    </message>
    <message>
        <source>Minimum Ø</source>
        <translation>Minimaler Ø</translation>
    </message>
    <message>
        <source>Maximum Ø</source>
        <translation>Maximaler Ø</translation>
    </message>
    <message>
        <source>Curved reformation along the path (stretched: the path straight, distances true along it), turned %1° about the path; window width %2, level %3.</source>
        <translation>Gekrümmte Reformation entlang des Pfads (gestreckt: der Pfad gerade, Abstände entlang des Pfads maßstabsgetreu), um %1° um den Pfad gedreht; Fensterbreite %2, Fenstermitte %3.</translation>
    </message>
</context>
<context>
    <name>vv::app::SegmentationText</name>
    <message>
        <source>towards the head</source>
        <translation>kopfwärts</translation>
    </message>
    <message>
        <source>towards the feet</source>
        <translation>fußwärts</translation>
    </message>
    <message>
        <source>to the patient&apos;s left</source>
        <translation>zur linken Seite des Patienten</translation>
    </message>
    <message>
        <source>to the patient&apos;s right</source>
        <translation>zur rechten Seite des Patienten</translation>
    </message>
    <message>
        <source>anteriorly</source>
        <translation>nach anterior</translation>
    </message>
    <message>
        <source>posteriorly</source>
        <translation>nach posterior</translation>
    </message>
    <message>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>The vessel may be cut off: a bright tube continues %1 mm %2 past the segmentation&apos;s end at (%3, %4, %5) mm, where the signal may fade.</source>
        <translation>Das Gefäß ist möglicherweise abgeschnitten: Eine helle Röhre setzt sich %1 mm %2 über das Ende der Segmentierung bei (%3, %4, %5) mm fort, wo das Signal schwächer werden kann.</translation>
    </message>
    <message>
        <source>CT angiography default</source>
        <translation>Voreinstellung für CT-Angiographie</translation>
    </message>
    <message>
        <source>from the histogram (Otsu)</source>
        <translation>aus dem Histogramm (Otsu)</translation>
    </message>
    <message>
        <source>the volume&apos;s only value</source>
        <translation>der einzige Wert des Volumens</translation>
    </message>
    <message>
        <source>chosen in the Segmentation panel</source>
        <translation>im Bereich Segmentierung gewählt</translation>
    </message>
    <message>
        <source>chosen in the series dialog</source>
        <translation>in der Serienauswahl gewählt</translation>
    </message>
    <message>
        <source>saved in the session</source>
        <translation>in der Sitzung gespeichert</translation>
    </message>
    <message>
        <source>given with --threshold</source>
        <translation>mit --threshold angegeben</translation>
    </message>
    <message>
        <source>Segments</source>
        <translation>Segmente</translation>
    </message>
    <message>
        <source>Threshold</source>
        <translation>Schwellenwert</translation>
    </message>
    <message>
        <source>%1 to %2%3 (%4)</source>
        <translation>%1 bis %2%3 (%4)</translation>
    </message>
    <message>
        <source>Intensity correction</source>
        <translation>Intensitätskorrektur</translation>
    </message>
    <message>
        <source>on (MR signal fall-off divided out; gain %1 to %2)</source>
        <translation>ein (MR-Signalabfall herausgerechnet; Verstärkung %1 bis %2)</translation>
    </message>
    <message>
        <source>the one under voxel (%1, %2, %3)</source>
        <translation>die unter dem Voxel (%1, %2, %3)</translation>
    </message>
    <message numerus="yes">
        <source>the %n largest</source>
        <translation>
            <numerusform>die %n größte</numerusform>
            <numerusform>die %n größten</numerusform>
        </translation>
    </message>
    <message>
        <source>Components</source>
        <translation>Komponenten</translation>
    </message>
    <message>
        <source>%1: kept %2 of %3</source>
        <translation>%1: %2 von %3 behalten</translation>
    </message>
    <message>
        <source>Bone removal</source>
        <translation>Knochenentfernung</translation>
    </message>
    <message numerus="yes">
        <source>%n more such end(s).</source>
        <translation>
            <numerusform>%n weiteres solches Ende.</numerusform>
            <numerusform>%n weitere solche Enden.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>vv::app::Settings</name>
    <message>
        <source>Show the Void Space Surface</source>
        <translation>Void Space Surface anzeigen</translation>
    </message>
    <message>
        <source>Power p</source>
        <translation>Exponent p</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <source>Step k</source>
        <translation>Schrittweite k</translation>
    </message>
    <message>
        <source>Colour scale</source>
        <translation>Farbskala</translation>
    </message>
    <message>
        <source>Iso-lines</source>
        <translation>Isolinien</translation>
    </message>
    <message>
        <source>Iso-line width</source>
        <translation>Breite der Isolinien</translation>
    </message>
    <message>
        <source>Iso-line strength</source>
        <translation>Stärke der Isolinien</translation>
    </message>
    <message>
        <source>Lighting</source>
        <translation>Beleuchtung</translation>
    </message>
    <message>
        <source>VSS opacity</source>
        <translation>Deckkraft der VSS</translation>
    </message>
    <message>
        <source>Depth range</source>
        <translation>Tiefenbereich</translation>
    </message>
    <message>
        <source>Near depth</source>
        <translation>Nahe Tiefe</translation>
    </message>
    <message>
        <source>Far depth</source>
        <translation>Ferne Tiefe</translation>
    </message>
    <message>
        <source>Ambient occlusion</source>
        <translation>Umgebungsverdeckung</translation>
    </message>
    <message>
        <source>AO radius</source>
        <translation>AO-Radius</translation>
    </message>
    <message>
        <source>AO strength</source>
        <translation>AO-Stärke</translation>
    </message>
    <message>
        <source>Vessel cue</source>
        <translation>Gefäß-Tiefenhinweis</translation>
    </message>
    <message>
        <source>Fog strength</source>
        <translation>Nebelstärke</translation>
    </message>
    <message>
        <source>Fresnel exponent</source>
        <translation>Fresnel-Exponent</translation>
    </message>
    <message>
        <source>Array</source>
        <translation>Datenfeld</translation>
    </message>
    <message>
        <source>Colour map</source>
        <translation>Farbtabelle</translation>
    </message>
    <message>
        <source>Colour range minimum</source>
        <translation>Minimum des Farbbereichs</translation>
    </message>
    <message>
        <source>Colour range maximum</source>
        <translation>Maximum des Farbbereichs</translation>
    </message>
    <message>
        <source>No-data colour</source>
        <translation>Farbe ohne Daten</translation>
    </message>
    <message>
        <source>Legend title</source>
        <translation>Legendentitel</translation>
    </message>
    <message>
        <source>Vessel colour</source>
        <translation>Gefäßfarbe</translation>
    </message>
    <message>
        <source>Light azimuth</source>
        <translation>Azimut des Lichts</translation>
    </message>
    <message>
        <source>Light elevation</source>
        <translation>Elevation des Lichts</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Deckkraft</translation>
    </message>
    <message>
        <source>Object colour</source>
        <translation>Objektfarbe</translation>
    </message>
    <message>
        <source>Background</source>
        <translation>Hintergrund</translation>
    </message>
    <message>
        <source>Show legends</source>
        <translation>Legenden anzeigen</translation>
    </message>
    <message>
        <source>Anti-aliasing (FXAA)</source>
        <translation>Kantenglättung (FXAA)</translation>
    </message>
    <message>
        <source>Colour-map bins</source>
        <translation>Farbstufen</translation>
    </message>
    <message>
        <source>Show the orientation marker</source>
        <translation>Orientierungsmarke anzeigen</translation>
    </message>
    <message>
        <source>Show the scale bar (at the focal plane)</source>
        <translation>Maßstab anzeigen (in der Fokusebene)</translation>
    </message>
    <message>
        <source>Values</source>
        <translation>Werte</translation>
    </message>
    <message>
        <source>Smooth coarse meshes up close</source>
        <translation>Grobe Netze aus der Nähe glätten</translation>
    </message>
</context>
<context>
    <name>vv::app::SliceReport</name>
    <message>
        <source>The segmentation is not drawn.</source>
        <translation>Die Segmentierung ist nicht eingezeichnet.</translation>
    </message>
    <message>
        <source>Coloured fill and outline: the segmentation.</source>
        <translation>Farbige Fläche und Umriss: die Segmentierung.</translation>
    </message>
    <message>
        <source>Coloured fill: the segmentation.</source>
        <translation>Farbige Fläche: die Segmentierung.</translation>
    </message>
    <message>
        <source>Coloured outline: the segmentation.</source>
        <translation>Farbiger Umriss: die Segmentierung.</translation>
    </message>
    <message>
        <source>%1 slice at %2, window %3</source>
        <extracomment>%1 plane (Axial), %2 position along its normal (S 12.5 mm), %3 window (W 600 HU L 300 HU)</extracomment>
        <translation>%1, Schicht bei %2, Fenster %3</translation>
    </message>
    <message>
        <source>%1 (%2 preset)</source>
        <extracomment>%1 the slice&apos;s caption so far, %2 the window preset (CTA)</extracomment>
        <translation>%1 (Fenstervorgabe %2)</translation>
    </message>
</context>
<context>
    <name>vv::gui::AnalysisTask</name>
    <message>
        <source>The scene has no vessel surface to analyse.</source>
        <translation>Die Szene hat keine Gefäßoberfläche, die analysiert werden kann.</translation>
    </message>
    <message>
        <source>The surface cannot be analysed.</source>
        <translation>Die Oberfläche kann nicht analysiert werden.</translation>
    </message>
</context>
<context>
    <name>vv::gui::CrossSectionView</name>
    <message>
        <source>The section perpendicular to the path at the cursor; the wheel or the arrow keys move along the path</source>
        <translation>Der Schnitt senkrecht zum Pfad am Cursor; Mausrad oder Pfeiltasten bewegen ihn entlang des Pfads</translation>
    </message>
    <message>
        <source>No closed lumen contour here</source>
        <translation>Hier keine geschlossene Lumenkontur</translation>
    </message>
    <message>
        <source>Minimum %1, maximum %2</source>
        <translation>Minimum %1, Maximum %2</translation>
    </message>
    <message>
        <source>Equivalent %1, area %2</source>
        <translation>Äquivalent %1, Fläche %2</translation>
    </message>
    <message>
        <source>At an end or a junction: not a vessel size</source>
        <translation>An einem Ende oder einer Verzweigung: keine Gefäßgröße</translation>
    </message>
    <message>
        <source>Find the centrelines to see the cross-section</source>
        <translation>Finden Sie die Mittellinien, um den Querschnitt zu sehen</translation>
    </message>
    <message>
        <source>%1 along the path</source>
        <translation>%1 entlang des Pfads</translation>
    </message>
</context>
<context>
    <name>vv::gui::CurvedReformation</name>
    <message>
        <source>The volume along the path, straightened (distances true along it); a click moves the cursor</source>
        <translation>Das Volumen entlang des Pfads, gestreckt (Abstände entlang des Pfads maßstabsgetreu); ein Klick bewegt den Cursor</translation>
    </message>
    <message>
        <source>Rotation about the path</source>
        <translation>Drehung um den Pfad</translation>
    </message>
    <message>
        <source>Find the centrelines to see the curved reformation</source>
        <translation>Finden Sie die Mittellinien, um die gekrümmte Reformation zu sehen</translation>
    </message>
    <message>
        <source>The curved reformation needs an image series</source>
        <translation>Die gekrümmte Reformation braucht eine Bildserie</translation>
    </message>
</context>
<context>
    <name>vv::gui::DiameterProfile</name>
    <message>
        <source>Find the centrelines to see the diameter profile</source>
        <translation>Finden Sie die Mittellinien, um das Durchmesserprofil zu sehen</translation>
    </message>
    <message>
        <source>Diameters along the path: %1 → %2</source>
        <translation>Durchmesser entlang des Pfads: %1 → %2</translation>
    </message>
    <message>
        <source>Distance along the path (mm)</source>
        <translation>Abstand entlang des Pfads (mm)</translation>
    </message>
    <message>
        <source>Area (mm²)</source>
        <translation>Fläche (mm²)</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <source>Minimum</source>
        <translation>Minimum</translation>
    </message>
    <message>
        <source>Maximum</source>
        <translation>Maximum</translation>
    </message>
    <message>
        <source>Equivalent</source>
        <translation>Äquivalent</translation>
    </message>
    <message>
        <source>Stenosis</source>
        <translation>Stenose</translation>
    </message>
    <message>
        <source>Ø (mm)</source>
        <translation>Ø (mm)</translation>
    </message>
</context>
<context>
    <name>vv::gui::DicomMenu</name>
    <message>
        <source>&amp;DICOM</source>
        <translation>DI&amp;COM</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <source>&amp;Query PACS…</source>
        <translation>PACS &amp;abfragen…</translation>
    </message>
</context>
<context>
    <name>vv::gui::DocumentController</name>
    <message>
        <source>Cannot open</source>
        <translation>Öffnen nicht möglich</translation>
    </message>
    <message numerus="yes">
        <source>%1: no DICOM images found (%n file(s) skipped)</source>
        <translation>
            <numerusform>%1: keine DICOM-Bilder gefunden (%n Datei übersprungen)</numerusform>
            <numerusform>%1: keine DICOM-Bilder gefunden (%n Dateien übersprungen)</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot open the session</source>
        <translation>Die Sitzung kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>Cannot save the session</source>
        <translation>Die Sitzung kann nicht gespeichert werden</translation>
    </message>
    <message>
        <source>Meshes (%1)</source>
        <translation>Netze (%1)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>vv::gui::EngineTexts</name>
    <message>
        <source>Generating vessel tree</source>
        <translation>Gefäßbaum wird erzeugt</translation>
    </message>
    <message>
        <source>Extracting surface</source>
        <translation>Oberfläche wird extrahiert</translation>
    </message>
    <message>
        <source>Smoothing surface</source>
        <translation>Oberfläche wird geglättet</translation>
    </message>
    <message>
        <source>Computing normals</source>
        <translation>Normalen werden berechnet</translation>
    </message>
    <message>
        <source>Assigning vessel data</source>
        <translation>Gefäßdaten werden zugeordnet</translation>
    </message>
    <message>
        <source>Voxelising the demo tree</source>
        <translation>Demo-Gefäßbaum wird voxelisiert</translation>
    </message>
    <message>
        <source>Listing DICOM files</source>
        <translation>DICOM-Dateien werden aufgelistet</translation>
    </message>
    <message>
        <source>Reading DICOM headers</source>
        <translation>DICOM-Header werden gelesen</translation>
    </message>
    <message>
        <source>Loading DICOM series</source>
        <translation>DICOM-Serie wird geladen</translation>
    </message>
    <message>
        <source>Reading DICOM SEG</source>
        <translation>DICOM-SEG wird gelesen</translation>
    </message>
    <message>
        <source>Writing the CT series</source>
        <translation>CT-Serie wird geschrieben</translation>
    </message>
    <message>
        <source>Extracting the surface</source>
        <translation>Oberfläche wird extrahiert</translation>
    </message>
    <message>
        <source>Merging points</source>
        <translation>Punkte werden zusammengeführt</translation>
    </message>
    <message>
        <source>simplifying</source>
        <translation>wird vereinfacht</translation>
    </message>
    <message>
        <source>Segmenting</source>
        <translation>Segmentierung läuft</translation>
    </message>
    <message>
        <source>depth</source>
        <translation>Tiefe</translation>
    </message>
    <message>
        <source>solving the VSS</source>
        <translation>VSS wird berechnet</translation>
    </message>
    <message>
        <source>rendering tiles</source>
        <translation>Kacheln werden gerendert</translation>
    </message>
    <message>
        <source>rendering</source>
        <translation>wird gerendert</translation>
    </message>
    <message>
        <source>Reading the patient and study</source>
        <translation>Patient und Studie werden gelesen</translation>
    </message>
    <message>
        <source>Rendering the image</source>
        <translation>Bild wird gerendert</translation>
    </message>
    <message>
        <source>Rendering the report&apos;s view</source>
        <translation>Ansicht des Berichts wird gerendert</translation>
    </message>
    <message>
        <source>Rendering the second view</source>
        <translation>Zweite Ansicht wird gerendert</translation>
    </message>
    <message>
        <source>Laying out the PDF</source>
        <translation>PDF wird gesetzt</translation>
    </message>
    <message>
        <source>Writing the files</source>
        <translation>Dateien werden geschrieben</translation>
    </message>
    <message>
        <source>Checking %1</source>
        <translation>%1 wird geprüft</translation>
    </message>
    <message>
        <source>Reading %1</source>
        <translation>%1 wird gelesen</translation>
    </message>
    <message>
        <source>Converting %1</source>
        <translation>%1 wird umgewandelt</translation>
    </message>
    <message>
        <source>Loaded %1</source>
        <translation>%1 geladen</translation>
    </message>
    <message>
        <source>CT angiography default: %1 to %2</source>
        <translation>Voreinstellung für CT-Angiographie: %1 bis %2</translation>
    </message>
    <message>
        <source>Constant volume: its only value, %1</source>
        <translation>Konstantes Volumen: sein einziger Wert, %1</translation>
    </message>
    <message>
        <source>From the histogram: Otsu threshold of the voxels above the background, %1 to %2</source>
        <translation>Aus dem Histogramm: Otsu-Schwelle der Voxel über dem Hintergrund, %1 bis %2</translation>
    </message>
    <message>
        <source>From the histogram: Otsu threshold, %1 to %2</source>
        <translation>Aus dem Histogramm: Otsu-Schwelle, %1 bis %2</translation>
    </message>
    <message>
        <source>A value is out of its range.</source>
        <translation>Ein Wert liegt außerhalb seines Bereichs.</translation>
    </message>
    <message>
        <source>The graphics system failed.</source>
        <translation>Das Grafiksystem hat versagt.</translation>
    </message>
    <message>
        <source>An unexpected error occurred.</source>
        <translation>Ein unerwarteter Fehler ist aufgetreten.</translation>
    </message>
    <message>
        <source>An unexpected error occurred (%1).</source>
        <translation>Ein unerwarteter Fehler ist aufgetreten (%1).</translation>
    </message>
    <message>
        <source>%1 could not be read.</source>
        <translation>%1 konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <source>A file could not be read.</source>
        <translation>Eine Datei konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <source>%1 could not be written.</source>
        <translation>%1 konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>A file could not be written.</source>
        <translation>Eine Datei konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>%1 is damaged, empty or not of a supported type.</source>
        <translation>%1 ist beschädigt, leer oder hat kein unterstütztes Format.</translation>
    </message>
    <message>
        <source>The data is damaged, empty or not of a supported type.</source>
        <translation>Die Daten sind beschädigt, leer oder haben kein unterstütztes Format.</translation>
    </message>
    <message>
        <source>%1 holds a value out of its range.</source>
        <translation>%1 enthält einen Wert außerhalb des zulässigen Bereichs.</translation>
    </message>
    <message>
        <source>The graphics system failed (%1).</source>
        <translation>Das Grafiksystem ist ausgefallen (%1).</translation>
    </message>
    <message>
        <source>Estimating the signal fall-off</source>
        <translation>Signalabfall wird geschätzt</translation>
    </message>
    <message>
        <source>Correcting the signal fall-off</source>
        <translation>Signalabfall wird korrigiert</translation>
    </message>
    <message>
        <source>Checking the segmentation&apos;s ends</source>
        <translation>Enden der Segmentierung werden geprüft</translation>
    </message>
    <message>
        <source>Preparing the surface</source>
        <translation>Oberfläche wird vorbereitet</translation>
    </message>
    <message>
        <source>Tetrahedralising the surface</source>
        <translation>Oberfläche wird tetraedrisiert</translation>
    </message>
    <message>
        <source>Joining the Voronoi diagram</source>
        <translation>Voronoi-Diagramm wird zusammengefügt</translation>
    </message>
    <message>
        <source>Finding the vessels&apos; ends</source>
        <translation>Gefäßenden werden gesucht</translation>
    </message>
    <message>
        <source>Tracing the centrelines</source>
        <translation>Mittellinien werden verfolgt</translation>
    </message>
    <message>
        <source>Centrelines done</source>
        <translation>Mittellinien fertig</translation>
    </message>
    <message>
        <source>Cutting the sections</source>
        <translation>Querschnitte werden gelegt</translation>
    </message>
</context>
<context>
    <name>vv::gui::ExportDialog</name>
    <message>
        <source>%1 already exists in %2. Replace it?</source>
        <translation>%1 ist in %2 bereits vorhanden. Ersetzen?</translation>
    </message>
    <message>
        <source>These files already exist:
%1
Replace them?</source>
        <translation>Diese Dateien sind bereits vorhanden:
%1
Ersetzen?</translation>
    </message>
    <message>
        <source>&amp;Replace</source>
        <translation>&amp;Ersetzen</translation>
    </message>
</context>
<context>
    <name>vv::gui::ExportImageDialog</name>
    <message>
        <source>Export Image</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <source>Export image</source>
        <translation>Bild exportieren</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Datei:</translation>
    </message>
    <message>
        <source>View size (%1 × %2)</source>
        <translation>Ansichtsgröße (%1 × %2)</translation>
    </message>
    <message>
        <source>Full HD (1920 × 1080)</source>
        <translation>Full HD (1920 × 1080)</translation>
    </message>
    <message>
        <source>4K UHD (3840 × 2160)</source>
        <translation>4K UHD (3840 × 2160)</translation>
    </message>
    <message>
        <source>8K UHD (7680 × 4320)</source>
        <translation>8K UHD (7680 × 4320)</translation>
    </message>
    <message>
        <source>Custom</source>
        <translation>Benutzerdefiniert</translation>
    </message>
    <message>
        <source>&amp;Size:</source>
        <translation>&amp;Größe:</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Width × height:</source>
        <translation>Breite × Höhe:</translation>
    </message>
    <message>
        <source>&amp;Keep the view&apos;s aspect ratio</source>
        <translation>Seitenverhältnis der Ansicht &amp;beibehalten</translation>
    </message>
    <message>
        <source>&amp;Legends</source>
        <translation>&amp;Legenden</translation>
    </message>
    <message>
        <source>&amp;Transparent background</source>
        <translation>&amp;Transparenter Hintergrund</translation>
    </message>
    <message>
        <source>Pixels without vessels or VSS get alpha 0</source>
        <translation>Pixel ohne Gefäße oder VSS erhalten Alpha 0</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>Choose a file name for the image.</source>
        <translation>Wählen Sie einen Dateinamen für das Bild.</translation>
    </message>
    <message>
        <source>%1 is a folder; choose a file name for the image.</source>
        <translation>%1 ist ein Ordner; wählen Sie einen Dateinamen für das Bild.</translation>
    </message>
    <message>
        <source>%1 × %2 pixels is larger than 8K: images are at most 7680 × 4320 pixels (either way round).</source>
        <translation>%1 × %2 Pixel ist größer als 8K: Bilder haben höchstens 7680 × 4320 Pixel (in beiden Ausrichtungen).</translation>
    </message>
    <message>
        <source>There is no data on screen to export.</source>
        <translation>Es werden keine Daten angezeigt, die exportiert werden könnten.</translation>
    </message>
    <message>
        <source>Exporting %1</source>
        <translation>%1 wird exportiert</translation>
    </message>
    <message>
        <source>Rendering %1 × %2</source>
        <translation>Rendern mit %1 × %2</translation>
    </message>
    <message>
        <source>Writing the PNG file</source>
        <translation>PNG-Datei wird geschrieben</translation>
    </message>
    <message>
        <source>Exported %1 (%2 × %3%4)</source>
        <translation>%1 exportiert (%2 × %3%4)</translation>
    </message>
    <message>
        <source>, transparent background</source>
        <translation>, transparenter Hintergrund</translation>
    </message>
    <message>
        <source>The image shows exactly what the view shows. A preset sets its exact size and turns this off when its shape differs from the view&apos;s.</source>
        <translation>Das Bild zeigt genau, was die Ansicht zeigt. Eine Vorgabe setzt genau ihre Größe und schaltet dies aus, wenn ihr Seitenverhältnis von dem der Ansicht abweicht.</translation>
    </message>
    <message>
        <source>The image (%1) is wider than the view (%2): it shows more at the left and right than the view does.</source>
        <translation>Das Bild (%1) ist breiter als die Ansicht (%2): Es zeigt links und rechts mehr als die Ansicht.</translation>
    </message>
    <message>
        <source>The image (%1) is narrower than the view (%2): it leaves out part of the view at the left and right.</source>
        <translation>Das Bild (%1) ist schmaler als die Ansicht (%2): Links und rechts fehlt ein Teil der Ansicht.</translation>
    </message>
</context>
<context>
    <name>vv::gui::ExportSurfaceDialog</name>
    <message>
        <source>Export Surface</source>
        <translation>Oberfläche exportieren</translation>
    </message>
    <message>
        <source>STL, binary (3-D printing)</source>
        <translation>STL, binär (3D-Druck)</translation>
    </message>
    <message>
        <source>VTK polydata (labels and provenance)</source>
        <translation>VTK-Polydaten (Labels und Herkunft)</translation>
    </message>
    <message>
        <source>PLY, binary</source>
        <translation>PLY, binär</translation>
    </message>
    <message>
        <source>Export surface</source>
        <translation>Oberfläche exportieren</translation>
    </message>
    <message>
        <source>Surfaces (*.stl *.vtp *.ply)</source>
        <translation>Oberflächen (*.stl *.vtp *.ply)</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Datei:</translation>
    </message>
    <message>
        <source>F&amp;ormat:</source>
        <translation>F&amp;ormat:</translation>
    </message>
    <message>
        <source>The surface on screen: %1 triangles.</source>
        <translation>Die angezeigte Oberfläche: %1 Dreiecke.</translation>
    </message>
    <message>
        <source>Coordinates: DICOM patient LPS, millimetres, as the scene (x to the patient&apos;s left, y posterior, z to the head). Tools that expect RAS: negate x and y. The file names the series and the settings that made it.</source>
        <translation>Koordinaten: DICOM-Patientensystem LPS in Millimetern wie die Szene (x zur linken Seite des Patienten, y nach posterior, z zum Kopf). Für Programme, die RAS erwarten: x und y negieren. Die Datei nennt die Serie und die Einstellungen, mit denen sie entstand.</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>Choose a file name for the surface.</source>
        <translation>Wählen Sie einen Dateinamen für die Oberfläche.</translation>
    </message>
    <message>
        <source>%1 is a folder; choose a file name for the surface.</source>
        <translation>%1 ist ein Ordner; wählen Sie einen Dateinamen für die Oberfläche.</translation>
    </message>
    <message>
        <source>%1: surfaces are written as .stl, .vtp or .ply files.</source>
        <translation>%1: Oberflächen werden als .stl-, .vtp- oder .ply-Dateien geschrieben.</translation>
    </message>
    <message>
        <source>There is no segmented surface to export.</source>
        <translation>Es gibt keine segmentierte Oberfläche zum Exportieren.</translation>
    </message>
    <message>
        <source>Exporting %1</source>
        <translation>%1 wird exportiert</translation>
    </message>
    <message>
        <source>Writing the surface</source>
        <translation>Die Oberfläche wird geschrieben</translation>
    </message>
    <message>
        <source>Exported %1 (%2 triangles, patient LPS mm)</source>
        <translation>%1 exportiert (%2 Dreiecke, Patienten-LPS in mm)</translation>
    </message>
    <message>
        <source>The applied segmentation&apos;s surface: %1 triangles.</source>
        <translation>Die Oberfläche der angewendeten Segmentierung: %1 Dreiecke.</translation>
    </message>
</context>
<context>
    <name>vv::gui::ExportWorker</name>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Export</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Wird abgebrochen…</translation>
    </message>
    <message>
        <source>Export cancelled: nothing was written</source>
        <translation>Export abgebrochen: es wurde nichts geschrieben</translation>
    </message>
    <message>
        <source>Export failed: %1</source>
        <translation>Export fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Cannot export</source>
        <translation>Export nicht möglich</translation>
    </message>
</context>
<context>
    <name>vv::gui::HelpTexts</name>
    <message>
        <source>not initialised</source>
        <translation>nicht initialisiert</translation>
    </message>
    <message>
        <source>built with %1</source>
        <translation>erstellt mit %1</translation>
    </message>
    <message>
        <source>&lt;h3&gt;VesselView %1&lt;/h3&gt;&lt;p&gt;A workstation for vessel trees: meshes with wall shear stress, pressure and other parameters on the vessel wall, and Void Space Surfaces.&lt;/p&gt;&lt;p&gt;OpenGL: %2&lt;/p&gt;&lt;p&gt;Libraries: %3&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;VesselView %1&lt;/h3&gt;&lt;p&gt;Ein Arbeitsplatz für Gefäßbäume: Oberflächennetze mit Wandschubspannung, Druck und weiteren Parametern auf der Gefäßwand sowie Void Space Surfaces.&lt;/p&gt;&lt;p&gt;OpenGL: %2&lt;/p&gt;&lt;p&gt;Bibliotheken: %3&lt;/p&gt;&lt;p&gt;Lizenziert unter der GNU General Public License, Version 3 oder neuer.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Drehen</translation>
    </message>
    <message>
        <source>left drag</source>
        <translation>Ziehen mit linker Maustaste</translation>
    </message>
    <message>
        <source>Pan</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <source>right or middle drag, Shift + left drag</source>
        <translation>Ziehen mit rechter oder mittlerer Maustaste, Umschalt + Ziehen mit linker Maustaste</translation>
    </message>
    <message>
        <source>Zoom</source>
        <translation>Zoomen</translation>
    </message>
    <message>
        <source>mouse wheel</source>
        <translation>Mausrad</translation>
    </message>
    <message>
        <source>Pick a point to measure</source>
        <translation>Einen Messpunkt wählen</translation>
    </message>
    <message>
        <source>Ctrl + click (any click in Measure mode)</source>
        <translation>Strg + Klick (im Messmodus jeder Klick)</translation>
    </message>
</context>
<context>
    <name>vv::gui::LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>System Default</source>
        <translation>Systemstandard</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>The language changes when VesselView starts again.</source>
        <translation>Die Sprache wechselt beim nächsten Start von VesselView.</translation>
    </message>
</context>
<context>
    <name>vv::gui::ListenerLimitsBox</name>
    <message>
        <source>Listener limits</source>
        <translation>Grenzen des Empfangsdienstes</translation>
    </message>
    <message>
        <source>Associations served at once. One more is refused for now (the sender may try again later), so that many senders at once cannot overload this workstation.</source>
        <translation>Gleichzeitig bediente Assoziationen. Eine weitere wird vorerst abgelehnt (der Sender kann es später erneut versuchen), damit viele Sender auf einmal diesen Arbeitsplatz nicht überlasten.</translation>
    </message>
    <message>
        <source>Open connections from the address of one configured node, at most the connections in all: one device that misbehaves cannot take every connection.</source>
        <translation>Offene Verbindungen von der Adresse eines eingerichteten Knotens, höchstens so viele wie Verbindungen insgesamt: Ein Gerät, das sich falsch verhält, kann nicht alle Verbindungen belegen.</translation>
    </message>
    <message>
        <source>Open connections in all, waiting or served, at least the simultaneous associations. A connection over a limit is closed at once.</source>
        <translation>Offene Verbindungen insgesamt, wartend oder bedient, mindestens so viele wie gleichzeitige Assoziationen. Eine Verbindung über einer Grenze wird sofort geschlossen.</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Seconds a new connection has to ask for an association before it is dropped: silent or slow connections cannot hold up the listener.</source>
        <translation>Sekunden, die eine neue Verbindung hat, um eine Assoziation anzufragen, bevor sie getrennt wird: Stumme oder langsame Verbindungen können den Empfangsdienst nicht aufhalten.</translation>
    </message>
    <message>
        <source>A larger instance is refused and not stored; the rest of the association goes on.</source>
        <translation>Eine größere Instanz wird abgelehnt und nicht gespeichert; der Rest der Assoziation geht weiter.</translation>
    </message>
    <message>
        <source>All instances of one association together, at least the largest instance. The instance that crosses it and all later ones are refused, and nothing of the association is kept.</source>
        <translation>Alle Instanzen einer Assoziation zusammen, mindestens die größte Instanz. Die Instanz, mit der sie überschritten wird, und alle späteren werden abgelehnt, und von der Assoziation wird nichts behalten.</translation>
    </message>
    <message>
        <source>Sim&amp;ultaneous associations:</source>
        <translation>G&amp;leichzeitige Assoziationen:</translation>
    </message>
    <message>
        <source>Connections per a&amp;ddress:</source>
        <translation>Verbindungen je A&amp;dresse:</translation>
    </message>
    <message>
        <source>C&amp;onnections in all:</source>
        <translation>Verbindungen &amp;insgesamt:</translation>
    </message>
    <message>
        <source>Association re&amp;quest deadline:</source>
        <translation>&amp;Frist für die Assoziationsanfrage:</translation>
    </message>
    <message>
        <source>Lar&amp;gest instance:</source>
        <translation>&amp;Maximale Instanzgröße:</translation>
    </message>
    <message>
        <source>Largest association:</source>
        <translation>Maximale Assoziationsgröße:</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Standardwerte wiederherstellen</translation>
    </message>
    <message>
        <source>Put the defaults into these fields; OK saves them</source>
        <translation>Die Standardwerte in diese Felder eintragen; OK speichert sie</translation>
    </message>
    <message>
        <source>Defaults: %1 associations, %2 per address, %3 in all, %4, %5 per instance, %6 per association. Addresses that are no configured node get at most %7 connections each, %8 together.</source>
        <translation>Standardwerte: %1 Assoziationen, %2 je Adresse, %3 insgesamt, %4, %5 je Instanz, %6 je Assoziation. Adressen, die kein eingerichteter Knoten sind, erhalten höchstens %7 Verbindungen je Adresse, %8 zusammen.</translation>
    </message>
</context>
<context>
    <name>vv::gui::ListenerService</name>
    <message>
        <source>DICOM listener: port %1</source>
        <translation>DICOM-Empfang: Port %1</translation>
    </message>
    <message>
        <source>DICOM listener failed: %1</source>
        <translation>DICOM-Empfang fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>DICOM listener off</source>
        <translation>DICOM-Empfang aus</translation>
    </message>
    <message>
        <source>the study store %1 cannot be opened</source>
        <translation>der Studienspeicher %1 lässt sich nicht öffnen</translation>
    </message>
    <message>
        <source>port %1 is in use by another program</source>
        <translation>Port %1 wird von einem anderen Programm belegt</translation>
    </message>
    <message>
        <source>cannot listen on %1, port %2</source>
        <translation>kann auf %1, Port %2 nicht empfangen</translation>
    </message>
    <message>
        <source>TLS is on, but our certificate, its key or the trusted CA certificates cannot be read or do not match</source>
        <translation>TLS ist eingeschaltet, aber unser Zertifikat, sein Schlüssel oder die vertrauenswürdigen CA-Zertifikate lassen sich nicht lesen oder passen nicht zusammen</translation>
    </message>
    <message>
        <source>%1 (TLS)</source>
        <translation>%1 (TLS)</translation>
    </message>
</context>
<context>
    <name>vv::gui::LocalStudiesBrowser</name>
    <message>
        <source>Series %1</source>
        <translation>Serie %1</translation>
    </message>
    <message>
        <source>1 image</source>
        <translation>1 Bild</translation>
    </message>
    <message>
        <source>%L1 images</source>
        <translation>%L1 Bilder</translation>
    </message>
    <message>
        <source>Local Studies</source>
        <translation>Lokale Studien</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Patient</translation>
    </message>
    <message>
        <source>Patient ID</source>
        <translation>Patienten-ID</translation>
    </message>
    <message>
        <source>Study date</source>
        <translation>Untersuchungsdatum</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>Modalities</source>
        <translation>Modalitäten</translation>
    </message>
    <message>
        <source>Series</source>
        <translation>Serien</translation>
    </message>
    <message>
        <source>&amp;Open</source>
        <translation>Ö&amp;ffnen</translation>
    </message>
    <message>
        <source>&amp;Refresh</source>
        <translation>&amp;Aktualisieren</translation>
    </message>
    <message>
        <source>The study store %1 cannot be read.</source>
        <translation>Der Studienspeicher %1 lässt sich nicht lesen.</translation>
    </message>
    <message>
        <source>1 study in %1</source>
        <translation>1 Studie in %1</translation>
    </message>
    <message>
        <source>%L1 studies in %2</source>
        <translation>%L1 Studien in %2</translation>
    </message>
    <message>
        <source>without date or description</source>
        <translation>ohne Datum und Beschreibung</translation>
    </message>
    <message>
        <source>of %1</source>
        <translation>vom %1</translation>
    </message>
    <message>
        <source>“%1”</source>
        <translation>„%1“</translation>
    </message>
    <message>
        <source>“%1” of %2</source>
        <translation>„%1“ vom %2</translation>
    </message>
    <message>
        <source>&amp;Delete…</source>
        <translation>&amp;Löschen…</translation>
    </message>
    <message>
        <source>Delete Study</source>
        <translation>Studie löschen</translation>
    </message>
    <message>
        <source>Delete the study %1 from the local study store? Its files are deleted from this computer.</source>
        <translation>Die Studie %1 aus dem lokalen Studienspeicher löschen? Ihre Dateien werden von diesem Computer gelöscht.</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>The study %1 is open — in this window or in another program — and was not deleted. Close it (open other data) and try again.</source>
        <translation>Die Studie %1 ist geöffnet – in diesem Fenster oder in einem anderen Programm – und wurde nicht gelöscht. Schließen Sie sie (öffnen Sie andere Daten) und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>The study %1 could not be deleted: the study store cannot be written.</source>
        <translation>Die Studie %1 konnte nicht gelöscht werden: In den Studienspeicher lässt sich nicht schreiben.</translation>
    </message>
    <message>
        <source>Reading the study store %1…</source>
        <translation>Der Studienspeicher %1 wird gelesen…</translation>
    </message>
</context>
<context>
    <name>vv::gui::LocalStudyActions</name>
    <message>
        <source>&amp;Local Studies…</source>
        <translation>&amp;Lokale Studien…</translation>
    </message>
    <message>
        <source>&amp;Send to PACS…</source>
        <translation>An PACS &amp;senden…</translation>
    </message>
    <message>
        <source>Open data first: there is nothing to send</source>
        <translation>Zuerst Daten öffnen: Es gibt nichts zu senden</translation>
    </message>
</context>
<context>
    <name>vv::gui::MainWindow</name>
    <message>
        <source>OpenGL 4.1 is not available</source>
        <translation>OpenGL 4.1 ist nicht verfügbar</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Open vessel meshes</source>
        <translation>Gefäßnetze öffnen</translation>
    </message>
    <message>
        <source>Open &amp;Demo</source>
        <translation>&amp;Demo öffnen</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Reset Camera</source>
        <translation>Kamera &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>&amp;Fit to Data</source>
        <translation>An Daten an&amp;passen</translation>
    </message>
    <message>
        <source>Show &amp;Legends</source>
        <translation>&amp;Legenden anzeigen</translation>
    </message>
    <message>
        <source>&amp;Measure Distance</source>
        <translation>Abstand &amp;messen</translation>
    </message>
    <message>
        <source>Click two points on the vessels: their distance and depth difference (Ctrl + click works without this mode)</source>
        <translation>Zwei Punkte auf den Gefäßen anklicken: ihr Abstand und ihr Tiefenunterschied (Strg + Klick geht auch ohne diesen Modus)</translation>
    </message>
    <message>
        <source>&amp;Clear Measurement</source>
        <translation>Messung &amp;löschen</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Seitenleisten</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>Anordnung &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>Reset to &amp;Defaults</source>
        <translation>Auf &amp;Standardwerte zurücksetzen</translation>
    </message>
    <message>
        <source>Display settings and panel layout as in a fresh installation</source>
        <translation>Darstellungseinstellungen und Anordnung der Seitenleisten wie nach einer Neuinstallation</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <source>&amp;About VesselView</source>
        <translation>&amp;Über VesselView</translation>
    </message>
    <message>
        <source>Void Space Surface</source>
        <translation>Void Space Surface</translation>
    </message>
    <message>
        <source>Functional parameters</source>
        <translation>Funktionelle Parameter</translation>
    </message>
    <message>
        <source>Display</source>
        <translation>Darstellung</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>Daten</translation>
    </message>
    <message>
        <source>VSS</source>
        <translation>VSS</translation>
    </message>
    <message>
        <source>Void Space Surface: a depth-coded surface in the space between the vessels</source>
        <translation>Void Space Surface: eine tiefenkodierte Fläche im Raum zwischen den Gefäßen</translation>
    </message>
    <message>
        <source>AO</source>
        <translation>AO</translation>
    </message>
    <message>
        <source>Ambient occlusion: shade the surface next to the vessels</source>
        <translation>Umgebungsverdeckung (Ambient Occlusion): die Fläche neben den Gefäßen abschatten</translation>
    </message>
    <message>
        <source>Colour-blind safe</source>
        <translation>Farbenblind-Modus</translation>
    </message>
    <message>
        <source>Colour-blind-safe mode (%1): dark-means-deep on the VSS, cividis on the vessels, no red/green depth cue</source>
        <translation>Modus für Farbfehlsichtige (%1): „Dunkel bedeutet tief“ auf der VSS, Cividis auf den Gefäßen, kein rot-grüner Tiefenhinweis</translation>
    </message>
    <message>
        <source>Keyboard Shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Bereit</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Wird abgebrochen…</translation>
    </message>
    <message numerus="yes">
        <source>%n files</source>
        <translation>
            <numerusform>%n Datei</numerusform>
            <numerusform>%n Dateien</numerusform>
        </translation>
    </message>
    <message>
        <source>demo vessel tree</source>
        <translation>Demo-Gefäßbaum</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <source>loading was cancelled</source>
        <translation>das Laden wurde abgebrochen</translation>
    </message>
    <message>
        <source>1 mesh</source>
        <translation>1 Netz</translation>
    </message>
    <message>
        <source>%1 meshes</source>
        <translation>%1 Netze</translation>
    </message>
    <message>
        <source>%1: %2, %3 triangles</source>
        <translation>%1: %2, %3 Dreiecke</translation>
    </message>
    <message>
        <source>%1: no data</source>
        <translation>%1: keine Daten</translation>
    </message>
    <message>
        <source>%1: %2 – %3</source>
        <translation>%1: %2 – %3</translation>
    </message>
    <message>
        <source>&amp;Clear Recent Files</source>
        <translation>Liste &amp;leeren</translation>
    </message>
    <message>
        <source>VSS: solving…</source>
        <translation>VSS: wird berechnet…</translation>
    </message>
    <message>
        <source>VSS: none</source>
        <translation>VSS: keine</translation>
    </message>
    <message>
        <source>VSS: preview</source>
        <translation>VSS: Vorschau</translation>
    </message>
    <message>
        <source>VSS: exact, %1 ms</source>
        <translation>VSS: exakt, %1 ms</translation>
    </message>
    <message>
        <source>About VesselView</source>
        <translation>Über VesselView</translation>
    </message>
    <message>
        <source>Open &amp;Session…</source>
        <translation>&amp;Sitzung öffnen…</translation>
    </message>
    <message>
        <source>Open session</source>
        <translation>Sitzung öffnen</translation>
    </message>
    <message>
        <source>VesselView sessions (*.vvs)</source>
        <translation>VesselView-Sitzungen (*.vvs)</translation>
    </message>
    <message>
        <source>Save Session &amp;As…</source>
        <translation>Sitzung speichern &amp;unter…</translation>
    </message>
    <message>
        <source>Save session</source>
        <translation>Sitzung speichern</translation>
    </message>
    <message>
        <source>Session saved to %1</source>
        <translation>Sitzung gespeichert unter %1</translation>
    </message>
    <message>
        <source>Open &amp;Folder…</source>
        <translation>&amp;Ordner öffnen…</translation>
    </message>
    <message>
        <source>Open DICOM folder</source>
        <translation>DICOM-Ordner öffnen</translation>
    </message>
    <message>
        <source>Choose a series</source>
        <translation>Serie auswählen</translation>
    </message>
    <message>
        <source>&amp;Export Image…</source>
        <translation>Bild &amp;exportieren…</translation>
    </message>
    <message>
        <source>Export Re&amp;port…</source>
        <translation>Be&amp;richt exportieren…</translation>
    </message>
    <message>
        <source>Segmentation</source>
        <translation>Segmentierung</translation>
    </message>
    <message>
        <source>Open data first: there is nothing to export</source>
        <translation>Zuerst Daten öffnen: es gibt nichts zu exportieren</translation>
    </message>
    <message>
        <source>Side Panel</source>
        <translation>Seitenleiste</translation>
    </message>
    <message>
        <source>Show &amp;Orientation Marker</source>
        <translation>&amp;Orientierungsmarke anzeigen</translation>
    </message>
    <message>
        <source>Show &amp;Scale Bar</source>
        <translation>&amp;Maßstab anzeigen</translation>
    </message>
    <message>
        <source>A length in mm, true at the focal plane (the depth of the centre of rotation); nearer parts look larger, farther ones smaller</source>
        <translation>Eine Länge in mm, maßstabsgetreu in der Fokusebene (der Tiefe des Drehzentrums); nähere Teile erscheinen größer, fernere kleiner</translation>
    </message>
    <message>
        <source>%1 (demo data) — VesselView</source>
        <translation>%1 (Demodaten) — VesselView</translation>
    </message>
    <message>
        <source>%1 — VesselView</source>
        <translation>%1 — VesselView</translation>
    </message>
    <message>
        <source>VSS: approximate (no error bound), %1 ms</source>
        <translation>VSS: genähert (ohne Fehlerschranke), %1 ms</translation>
    </message>
    <message>
        <source>VSS: within %1/255, %2 ms</source>
        <translation>VSS: Fehler ≤ %1/255, %2 ms</translation>
    </message>
    <message>
        <source>The segmented vessel surface as STL, VTP or PLY, in patient millimetres</source>
        <translation>Die segmentierte Gefäßoberfläche als STL, VTP oder PLY, in Patientenkoordinaten (mm)</translation>
    </message>
    <message>
        <source>Only for vessels segmented from a DICOM series: open one with File &gt; Open Folder…</source>
        <translation>Nur für aus einer DICOM-Serie segmentierte Gefäße: Öffnen Sie eine mit Datei &gt; Ordner öffnen…</translation>
    </message>
    <message>
        <source>Export S&amp;urface…</source>
        <translation>Oberfläche e&amp;xportieren…</translation>
    </message>
    <message>
        <source>The Segmentation panel shows a preview: apply it first (a preview is never exported or sent)</source>
        <translation>Der Bereich Segmentierung zeigt eine Vorschau: Wenden Sie sie zuerst an (eine Vorschau wird nie exportiert oder gesendet)</translation>
    </message>
    <message>
        <source>Session saved to %1, with the applied segmentation (the preview on screen was not applied)</source>
        <translation>Sitzung gespeichert unter %1, mit der angewendeten Segmentierung (die Vorschau auf dem Bildschirm wurde nicht angewendet)</translation>
    </message>
    <message>
        <source>&amp;Study</source>
        <translation>&amp;Studie</translation>
    </message>
    <message>
        <source>&amp;Run Study…</source>
        <translation>Studie &amp;durchführen…</translation>
    </message>
    <message>
        <source>&amp;Analyse Results…</source>
        <translation>Ergebnisse &amp;auswerten…</translation>
    </message>
    <message>
        <source>Smooth &amp;Coarse Meshes Up Close</source>
        <translation>&amp;Grobe Netze aus der Nähe glätten</translation>
    </message>
    <message>
        <source>Where a coarse mesh&apos;s facets are large on screen, draw it from a smooth (subdivided) copy, so that the lit void space surface shows no blob per facet; the status bar says how far the copy moves the wall</source>
        <translation>Wo die Facetten eines groben Netzes auf dem Bildschirm groß sind, es aus einer glatten (unterteilten) Kopie zeichnen, damit die beleuchtete Void Space Surface keinen Fleck je Facette zeigt; die Statusleiste nennt, wie weit die Kopie die Wand verschiebt</translation>
    </message>
    <message>
        <source>Coarse facets are drawn smoothed up close: the wall moves by at most %1 mm (%2 mm on average)</source>
        <translation>Grobe Facetten werden aus der Nähe geglättet gezeichnet: die Wand verschiebt sich um höchstens %1 mm (im Mittel %2 mm)</translation>
    </message>
    <message>
        <source>Smoothed up close: wall ≤ %1 mm</source>
        <translation>Aus der Nähe geglättet: Wand ≤ %1 mm</translation>
    </message>
    <message>
        <source>Analysis</source>
        <translation>Gefäßanalyse</translation>
    </message>
</context>
<context>
    <name>vv::gui::MeasureOverlay</name>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
</context>
<context>
    <name>vv::gui::MeasureTool</name>
    <message>
        <source>Measure: click a point on a vessel</source>
        <translation>Messen: einen Punkt auf einem Gefäß anklicken</translation>
    </message>
    <message>
        <source>object %1</source>
        <translation>Objekt %1</translation>
    </message>
    <message>
        <source>Measure: no vessel under the mouse</source>
        <translation>Messen: kein Gefäß unter dem Mauszeiger</translation>
    </message>
    <message>
        <source>The distance is the 3-D distance of points 1 and 2. The depth difference is measured along the current view direction and changes as the view turns. Esc clears.</source>
        <translation>Der Abstand ist der räumliche (3-D-)Abstand der Punkte 1 und 2. Der Tiefenunterschied wird entlang der aktuellen Blickrichtung gemessen und ändert sich, wenn die Ansicht gedreht wird. Esc löscht die Messung.</translation>
    </message>
    <message>
        <source>Measure: point 1 on %1; click a second point</source>
        <translation>Messen: Punkt 1 auf %1; einen zweiten Punkt anklicken</translation>
    </message>
    <message>
        <source>points 1 and 2 at the same depth</source>
        <translation>Punkte 1 und 2 in gleicher Tiefe</translation>
    </message>
    <message>
        <source>point 2 deeper by %1 mm</source>
        <translation>Punkt 2 um %1 mm tiefer</translation>
    </message>
    <message>
        <source>point 1 deeper by %1 mm</source>
        <translation>Punkt 1 um %1 mm tiefer</translation>
    </message>
    <message>
        <source>Distance 1–2: %1 mm · depth difference in this view: %2</source>
        <translation>Abstand 1–2: %1 mm · Tiefenunterschied in dieser Ansicht: %2</translation>
    </message>
</context>
<context>
    <name>vv::gui::MeshLoadTask</name>
    <message>
        <source>Generating the demo vessel tree</source>
        <translation>Demo-Gefäßbaum wird erzeugt</translation>
    </message>
    <message>
        <source>Loading %1</source>
        <translation>%1 wird geladen</translation>
    </message>
    <message numerus="yes">
        <source>Loading %n file(s)</source>
        <translation>
            <numerusform>%n Datei wird geladen</numerusform>
            <numerusform>%n Dateien werden geladen</numerusform>
        </translation>
    </message>
    <message>
        <source>Reading the DICOM headers of %1</source>
        <translation>DICOM-Header von %1 werden gelesen</translation>
    </message>
</context>
<context>
    <name>vv::gui::NetworkFailure</name>
    <message>
        <source>%1 answered.</source>
        <translation>%1 hat geantwortet.</translation>
    </message>
    <message>
        <source>%1 refused the connection: nobody listens there. Check the host name and port, and that the PACS is running and the firewall lets the port through.</source>
        <translation>%1 hat die Verbindung abgelehnt: Dort lauscht niemand. Prüfen Sie Hostname und Port, ob das PACS läuft und ob die Firewall den Port durchlässt.</translation>
    </message>
    <message>
        <source>%1 rejected the association. Check the node&apos;s AE title, and that the PACS knows our AE title, host and port.</source>
        <translation>%1 hat die Assoziation abgelehnt. Prüfen Sie den AE-Titel des Knotens und ob das PACS unseren AE-Titel, Host und Port kennt.</translation>
    </message>
    <message>
        <source>%1 did not answer in time. Check the host and port, the network and the firewall; the PACS may be overloaded.</source>
        <translation>%1 hat nicht rechtzeitig geantwortet. Prüfen Sie Host und Port, das Netzwerk und die Firewall; das PACS ist vielleicht überlastet.</translation>
    </message>
    <message>
        <source>The TLS connection to %1 failed. Check that the node speaks TLS on this port, the trusted CA certificate and our certificate and key files.</source>
        <translation>Die TLS-Verbindung zu %1 ist fehlgeschlagen. Prüfen Sie, ob der Knoten auf diesem Port TLS spricht, das vertrauenswürdige CA-Zertifikat sowie unsere Zertifikats- und Schlüsseldateien.</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>%1 closed the connection. Try again; if it keeps happening, check that the PACS knows our AE title, host and port, or ask the PACS administrator.</source>
        <translation>%1 hat die Verbindung geschlossen. Versuchen Sie es erneut; wenn es wieder geschieht, prüfen Sie, ob das PACS unseren AE-Titel, Host und Port kennt, oder fragen Sie die PACS-Administration.</translation>
    </message>
    <message>
        <source>the PACS closed the connection</source>
        <translation>Das PACS hat die Verbindung geschlossen</translation>
    </message>
    <message>
        <source>the PACS stopped answering</source>
        <translation>Das PACS antwortete nicht mehr</translation>
    </message>
    <message>
        <source>the PACS reported images it could not send</source>
        <translation>Das PACS meldete Bilder, die es nicht senden konnte</translation>
    </message>
    <message>
        <source>the secure connection failed</source>
        <translation>Die sichere Verbindung ist gescheitert</translation>
    </message>
    <message>
        <source>the PACS sent an answer that breaks the DICOM standard</source>
        <translation>Das PACS sandte eine Antwort, die gegen den DICOM-Standard verstößt</translation>
    </message>
    <message>
        <source>before the first image arrived</source>
        <translation>vor dem ersten Bild</translation>
    </message>
    <message>
        <source>after %1 of %2 images</source>
        <translation>nach %1 von %2 Bildern</translation>
    </message>
    <message>
        <source>Nothing was kept.</source>
        <translation>Nichts wurde behalten.</translation>
    </message>
    <message>
        <source>The transfer from %1 stopped %2: %3. %4Try again, or ask the PACS administrator if it keeps happening.</source>
        <translation>Die Übertragung von %1 brach %2 ab: %3. %4Versuchen Sie es erneut, oder fragen Sie die PACS-Administration, wenn es wieder geschieht.</translation>
    </message>
    <message numerus="yes">
        <source>after %n image(s)</source>
        <translation>
            <numerusform>nach %n Bild</numerusform>
            <numerusform>nach %n Bildern</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n image(s) of it were kept in the local study store.</source>
        <translation>
            <numerusform>%n Bild davon wurde im lokalen Studienspeicher behalten.</numerusform>
            <numerusform>%n Bilder davon wurden im lokalen Studienspeicher behalten.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <comment>node name (AE@host:port)</comment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>%1 reported a failure and did not complete the request. Try again; if it keeps happening, ask the PACS administrator.</source>
        <translation>%1 hat einen Fehler gemeldet und die Anfrage nicht abgeschlossen. Versuchen Sie es erneut; wenn es wieder geschieht, wenden Sie sich an die PACS-Administration.</translation>
    </message>
    <message>
        <source>%1 has more than %2 matches for this search. Narrow the search (patient name or ID, study date).</source>
        <translation>%1 hat für diese Suche mehr als %2 Treffer. Grenzen Sie die Suche ein (Patientenname oder -ID, Studiendatum).</translation>
    </message>
    <message>
        <source>The answer of %1 was refused: it breaks the DICOM standard or holds oversized values. Narrow the search; if it keeps happening, ask the PACS administrator.</source>
        <translation>Die Antwort von %1 wurde abgelehnt: Sie verletzt den DICOM-Standard oder enthält zu lange Werte. Grenzen Sie die Suche ein; wenn es wieder geschieht, wenden Sie sich an die PACS-Administration.</translation>
    </message>
    <message>
        <source>Nothing was asked of %1: a value is not valid in DICOM (a search field holds a backslash or more than 64 characters, or a date is not valid). Correct it and try again.</source>
        <translation>%1 wurde nicht angefragt: Ein Wert ist in DICOM nicht zulässig (ein Suchfeld enthält einen Backslash oder mehr als 64 Zeichen, oder ein Datum ist ungültig). Korrigieren Sie ihn und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>The request to %1 failed unexpectedly. Try again; if it keeps happening, give the details to the administrator.</source>
        <translation>Die Anfrage an %1 ist unerwartet fehlgeschlagen. Versuchen Sie es erneut; wenn es wieder geschieht, geben Sie die Details an die Administration weiter.</translation>
    </message>
</context>
<context>
    <name>vv::gui::NetworkPreferencesDialog</name>
    <message>
        <source>DICOM Network Preferences</source>
        <translation>DICOM-Netzwerkeinstellungen</translation>
    </message>
    <message>
        <source>This workstation</source>
        <translation>Diese Arbeitsstation</translation>
    </message>
    <message>
        <source>The AE title the PACS knows this workstation by</source>
        <translation>Der AE-Titel, unter dem das PACS diese Arbeitsstation kennt</translation>
    </message>
    <message>
        <source>Our &amp;AE title:</source>
        <translation>Unser &amp;AE-Titel:</translation>
    </message>
    <message>
        <source>&amp;Receive studies (listener on)</source>
        <translation>Studien &amp;empfangen (Empfangsdienst an)</translation>
    </message>
    <message>
        <source>Run the DICOM listener while VesselView runs: nodes allowed to send can push studies, and C-MOVE retrieves arrive here</source>
        <translation>Den DICOM-Empfangsdienst laufen lassen, solange VesselView läuft: Knoten mit Sendeerlaubnis können Studien schicken, und C-MOVE-Abrufe kommen hier an</translation>
    </message>
    <message>
        <source>Listener &amp;port:</source>
        <translation>&amp;Port des Empfangsdienstes:</translation>
    </message>
    <message>
        <source>This computer only</source>
        <translation>Nur dieser Rechner</translation>
    </message>
    <message>
        <source>All network interfaces</source>
        <translation>Alle Netzwerkschnittstellen</translation>
    </message>
    <message>
        <source>The IPv4 address of the interface to listen on: 127.0.0.1 for this computer only, 0.0.0.0 for all interfaces</source>
        <translation>Die IPv4-Adresse der Schnittstelle, auf der gelauscht wird: 127.0.0.1 nur für diesen Rechner, 0.0.0.0 für alle Schnittstellen</translation>
    </message>
    <message>
        <source>Listen on &amp;interface:</source>
        <translation>&amp;Schnittstelle:</translation>
    </message>
    <message>
        <source>Local study store</source>
        <translation>Lokaler Studienspeicher</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>Folder of the local study store</source>
        <translation>Ordner des lokalen Studienspeichers</translation>
    </message>
    <message>
        <source>&amp;Folder:</source>
        <translation>&amp;Ordner:</translation>
    </message>
    <message>
        <source>No limit</source>
        <translation>Keine Grenze</translation>
    </message>
    <message>
        <source>Above this size the oldest studies are removed first; open studies are never removed</source>
        <translation>Über dieser Größe werden die ältesten Studien zuerst entfernt; geöffnete Studien werden nie entfernt</translation>
    </message>
    <message>
        <source>Size &amp;limit:</source>
        <translation>&amp;Größengrenze:</translation>
    </message>
    <message>
        <source>PACS nodes</source>
        <translation>PACS-Knoten</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>AE title</source>
        <translation>AE-Titel</translation>
    </message>
    <message>
        <source>Host</source>
        <translation>Host</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Port</translation>
    </message>
    <message>
        <source>TLS</source>
        <translation>TLS</translation>
    </message>
    <message>
        <source>May send to us</source>
        <translation>Darf an uns senden</translation>
    </message>
    <message>
        <source>&amp;Add…</source>
        <translation>&amp;Hinzufügen…</translation>
    </message>
    <message>
        <source>&amp;Edit…</source>
        <translation>&amp;Bearbeiten…</translation>
    </message>
    <message>
        <source>Re&amp;move</source>
        <translation>E&amp;ntfernen</translation>
    </message>
    <message>
        <source>&amp;Test</source>
        <translation>&amp;Testen</translation>
    </message>
    <message>
        <source>C-ECHO: does the node answer and accept our AE title?</source>
        <translation>C-ECHO: Antwortet der Knoten und akzeptiert er unseren AE-Titel?</translation>
    </message>
    <message>
        <source>on</source>
        <translation>an</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>Our AE title</source>
        <translation>Unser AE-Titel</translation>
    </message>
    <message>
        <source>Testing…</source>
        <translation>Teste…</translation>
    </message>
    <message>
        <source>Testing %1…</source>
        <translation>Teste %1…</translation>
    </message>
    <message>
        <source>Success: %1 answered C-ECHO.</source>
        <translation>Erfolg: %1 hat auf C-ECHO geantwortet.</translation>
    </message>
    <message>
        <source>Listen on interface: enter an IPv4 address such as 127.0.0.1 (this computer only) or 0.0.0.0 (all interfaces).</source>
        <translation>Schnittstelle: Geben Sie eine IPv4-Adresse ein, etwa 127.0.0.1 (nur dieser Rechner) oder 0.0.0.0 (alle Schnittstellen).</translation>
    </message>
    <message>
        <source>Folder: choose a folder for the local study store.</source>
        <translation>Ordner: Wählen Sie einen Ordner für den lokalen Studienspeicher.</translation>
    </message>
    <message>
        <source>Listener uses TL&amp;S (encrypted DICOM)</source>
        <translation>Empfang mit TL&amp;S (verschlüsseltes DICOM)</translation>
    </message>
    <message>
        <source>Nodes sending to us must then use TLS with a certificate signed by the trusted CA</source>
        <translation>Knoten, die an uns senden, müssen dann TLS mit einem von der vertrauenswürdigen CA signierten Zertifikat verwenden</translation>
    </message>
    <message>
        <source>Ca&amp;ncel Test</source>
        <translation>Test abb&amp;rechen</translation>
    </message>
    <message>
        <source>Stop waiting for the node&apos;s answer</source>
        <translation>Nicht länger auf die Antwort des Knotens warten</translation>
    </message>
    <message>
        <source>Test cancelled.</source>
        <translation>Test abgebrochen.</translation>
    </message>
    <message>
        <source>Not saved: our AE title is not valid.</source>
        <translation>Nicht gespeichert: Unser AE-Titel ist ungültig.</translation>
    </message>
    <message>
        <source>Not saved: the listener port must be 1 to 65535.</source>
        <translation>Nicht gespeichert: Der Empfangsport muss zwischen 1 und 65535 liegen.</translation>
    </message>
    <message>
        <source>Not saved: the listener&apos;s TLS needs our certificate, its private key and the trusted CA certificate.</source>
        <translation>Nicht gespeichert: TLS für den Empfang braucht unser Zertifikat, seinen privaten Schlüssel und das vertrauenswürdige CA-Zertifikat.</translation>
    </message>
    <message>
        <source>Not saved: a node has no name.</source>
        <translation>Nicht gespeichert: Ein Knoten hat keinen Namen.</translation>
    </message>
    <message>
        <source>Not saved: two nodes are called &quot;%1&quot;.</source>
        <translation>Nicht gespeichert: Zwei Knoten heißen „%1“.</translation>
    </message>
    <message>
        <source>Not saved: the AE title, host or port of the node &quot;%1&quot; is not valid.</source>
        <translation>Nicht gespeichert: AE-Titel, Host oder Port des Knotens „%1“ sind ungültig.</translation>
    </message>
    <message>
        <source>Not saved: the listener limits do not fit together.</source>
        <translation>Nicht gespeichert: Die Grenzen des Empfangsdienstes passen nicht zusammen.</translation>
    </message>
    <message>
        <source>Timeouts</source>
        <translation>Zeitlimits</translation>
    </message>
    <message>
        <source>How long VesselView waits for a PACS node before it gives up</source>
        <translation>Wie lange VesselView auf einen PACS-Knoten wartet, bevor es aufgibt</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>How long the node&apos;s computer may take to accept the connection</source>
        <translation>Wie lange der Rechner des Knotens brauchen darf, um die Verbindung anzunehmen</translation>
    </message>
    <message>
        <source>How long the node may take to accept or reject the association, and to release it</source>
        <translation>Wie lange der Knoten brauchen darf, um die Assoziation anzunehmen oder abzulehnen und um sie freizugeben</translation>
    </message>
    <message>
        <source>How long the node may take for each answer (a search result, a status, an image); raise it for a slow PACS</source>
        <translation>Wie lange der Knoten für jede Antwort brauchen darf (ein Suchergebnis, einen Status, ein Bild); für ein langsames PACS erhöhen</translation>
    </message>
    <message>
        <source>Connect:</source>
        <translation>Verbindung:</translation>
    </message>
    <message>
        <source>Association:</source>
        <translation>Assoziation:</translation>
    </message>
    <message>
        <source>Each answer:</source>
        <translation>Jede Antwort:</translation>
    </message>
    <message>
        <source>Not saved: each timeout must be 1 to %L1 s.</source>
        <translation>Nicht gespeichert: Jedes Zeitlimit muss 1 bis %L1 s betragen.</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Standardwerte wiederherstellen</translation>
    </message>
    <message>
        <source>Put the default timeouts into these fields; OK saves them</source>
        <translation>Die Standard-Zeitlimits in diese Felder eintragen; OK speichert sie</translation>
    </message>
    <message>
        <source>Defaults: %1, %2, %3</source>
        <translation>Standardwerte: %1, %2, %3</translation>
    </message>
</context>
<context>
    <name>vv::gui::NodeEditDialog</name>
    <message>
        <source>%1: 1 to 16 characters (letters, digits, spaces, no backslash) are needed.</source>
        <translation>%1: 1 bis 16 Zeichen (Buchstaben, Ziffern, Leerzeichen, kein Backslash) sind nötig.</translation>
    </message>
    <message>
        <source>PACS Node</source>
        <translation>PACS-Knoten</translation>
    </message>
    <message>
        <source>e.g. Radiology PACS</source>
        <translation>z. B. Radiologie-PACS</translation>
    </message>
    <message>
        <source>May send studies to our listener</source>
        <translation>Darf Studien an unseren Empfangsdienst senden</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>&amp;AE title:</source>
        <translation>&amp;AE-Titel:</translation>
    </message>
    <message>
        <source>&amp;Host:</source>
        <translation>&amp;Host:</translation>
    </message>
    <message>
        <source>&amp;Port:</source>
        <translation>&amp;Port:</translation>
    </message>
    <message>
        <source>Use &amp;TLS (encrypted DICOM)</source>
        <translation>&amp;TLS verwenden (verschlüsseltes DICOM)</translation>
    </message>
    <message>
        <source>Name: give the node a name.</source>
        <translation>Name: Geben Sie dem Knoten einen Namen.</translation>
    </message>
    <message>
        <source>Name: another node is already called &quot;%1&quot;.</source>
        <translation>Name: Ein anderer Knoten heißt bereits „%1“.</translation>
    </message>
    <message>
        <source>AE title</source>
        <translation>AE-Titel</translation>
    </message>
    <message>
        <source>Host: enter the PACS&apos;s host name or IP address.</source>
        <translation>Host: Geben Sie den Hostnamen oder die IP-Adresse des PACS ein.</translation>
    </message>
</context>
<context>
    <name>vv::gui::PacsBrowser</name>
    <message>
        <source>any</source>
        <translation>beliebig</translation>
    </message>
    <message>
        <source>Query PACS</source>
        <translation>PACS abfragen</translation>
    </message>
    <message>
        <source>Search</source>
        <translation>Suche</translation>
    </message>
    <message>
        <source>&amp;Search</source>
        <translation>&amp;Suchen</translation>
    </message>
    <message>
        <source>&amp;Node:</source>
        <translation>&amp;Knoten:</translation>
    </message>
    <message>
        <source>Patient &amp;name:</source>
        <translation>Patienten&amp;name:</translation>
    </message>
    <message>
        <source>Patient &amp;ID:</source>
        <translation>Patienten-&amp;ID:</translation>
    </message>
    <message>
        <source>Study date &amp;from:</source>
        <translation>Studiendatum &amp;von:</translation>
    </message>
    <message>
        <source>&amp;to:</source>
        <translation>&amp;bis:</translation>
    </message>
    <message>
        <source>&amp;Modality:</source>
        <translation>&amp;Modalität:</translation>
    </message>
    <message>
        <source>&amp;Description:</source>
        <translation>B&amp;eschreibung:</translation>
    </message>
    <message>
        <source>&amp;Accession:</source>
        <translation>A&amp;uftragsnummer:</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Patient</translation>
    </message>
    <message>
        <source>Patient ID</source>
        <translation>Patienten-ID</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Datum</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>Modalities</source>
        <translation>Modalitäten</translation>
    </message>
    <message>
        <source>Accession</source>
        <translation>Auftragsnummer</translation>
    </message>
    <message>
        <source>Series</source>
        <translation>Serien</translation>
    </message>
    <message>
        <source>Number</source>
        <translation>Nummer</translation>
    </message>
    <message>
        <source>Modality</source>
        <translation>Modalität</translation>
    </message>
    <message>
        <source>Series description</source>
        <translation>Serienbeschreibung</translation>
    </message>
    <message>
        <source>Images</source>
        <translation>Bilder</translation>
    </message>
    <message>
        <source>Retrieve into the local study store</source>
        <translation>In den lokalen Studienspeicher abrufen</translation>
    </message>
    <message>
        <source>C-&amp;GET (direct)</source>
        <translation>C-&amp;GET (direkt)</translation>
    </message>
    <message>
        <source>C-M&amp;OVE to our listener</source>
        <translation>C-M&amp;OVE an unseren Empfangsdienst</translation>
    </message>
    <message>
        <source>Retrieve S&amp;tudy</source>
        <translation>S&amp;tudie abrufen</translation>
    </message>
    <message>
        <source>Retrieve S&amp;eries</source>
        <translation>Se&amp;rie abrufen</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>Abbre&amp;chen</translation>
    </message>
    <message>
        <source>O&amp;pen</source>
        <translation>Ö&amp;ffnen</translation>
    </message>
    <message>
        <source>Open the retrieved series in VesselView</source>
        <translation>Die abgerufene Serie in VesselView öffnen</translation>
    </message>
    <message>
        <source>%1 of %2 images</source>
        <translation>%1 von %2 Bildern</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Breche ab…</translation>
    </message>
    <message>
        <source>No PACS node is set up yet: add one in DICOM &gt; Preferences.</source>
        <translation>Noch kein PACS-Knoten eingerichtet: Fügen Sie einen unter DICOM &gt; Einstellungen hinzu.</translation>
    </message>
    <message>
        <source>Study date: &quot;from&quot; is after &quot;to&quot;.</source>
        <translation>Studiendatum: „von“ liegt nach „bis“.</translation>
    </message>
    <message>
        <source>Searching %1…</source>
        <translation>Durchsuche %1…</translation>
    </message>
    <message>
        <source>Studies found: %1.</source>
        <translation>Gefundene Studien: %1.</translation>
    </message>
    <message>
        <source>C-M&amp;OVE to our listener (%1, port %2)</source>
        <translation>C-M&amp;OVE an unseren Empfangsdienst (%1, Port %2)</translation>
    </message>
    <message>
        <source>Our listener is not running: turn it on in DICOM &gt; Preferences, or use C-GET.</source>
        <translation>Unser Empfangsdienst läuft nicht: Schalten Sie ihn unter DICOM &gt; Einstellungen ein, oder verwenden Sie C-GET.</translation>
    </message>
    <message>
        <source>C-MOVE needs our listener, and it is not running: turn it on in DICOM &gt; Preferences (nodes must be allowed to send to us), or use C-GET.</source>
        <translation>C-MOVE braucht unseren Empfangsdienst, und er läuft nicht: Schalten Sie ihn unter DICOM &gt; Einstellungen ein (der Knoten muss an uns senden dürfen), oder verwenden Sie C-GET.</translation>
    </message>
    <message>
        <source>Retrieving from %1…</source>
        <translation>Rufe von %1 ab…</translation>
    </message>
    <message>
        <source>Retrieve cancelled: nothing of it was kept.</source>
        <translation>Abruf abgebrochen: Nichts davon wurde behalten.</translation>
    </message>
    <message>
        <source>The PACS reports the move done, but our listener did not store the images. Check that the PACS knows our AE title, host and listener port.</source>
        <translation>Das PACS meldet den Transfer als erledigt, aber unser Empfangsdienst hat die Bilder nicht gespeichert. Prüfen Sie, ob das PACS unseren AE-Titel, Host und Empfangsport kennt.</translation>
    </message>
    <message>
        <source>Done: images retrieved into the local study store: %1.</source>
        <translation>Fertig: In den lokalen Studienspeicher abgerufene Bilder: %1.</translation>
    </message>
    <message>
        <source>Cancel Searc&amp;h</source>
        <translation>Suche &amp;abbrechen</translation>
    </message>
    <message>
        <source>Stop waiting for the PACS&apos;s answer</source>
        <translation>Nicht länger auf die Antwort des PACS warten</translation>
    </message>
    <message>
        <source>Search cancelled.</source>
        <translation>Suche abgebrochen.</translation>
    </message>
    <message>
        <source>e.g. Doe*</source>
        <translation>z. B. Muster*</translation>
    </message>
    <message>
        <source>The patient&apos;s name to search for, e.g. Doe*: * matches any text, ? any one character</source>
        <translation>Der gesuchte Patientenname, z. B. Muster*: * steht für beliebigen Text, ? für ein beliebiges Zeichen</translation>
    </message>
</context>
<context>
    <name>vv::gui::PacsWidgets</name>
    <message>
        <source>Details: %1</source>
        <translation>Details: %1</translation>
    </message>
    <message>
        <source> GB</source>
        <translation> GB</translation>
    </message>
</context>
<context>
    <name>vv::gui::PathField</name>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
</context>
<context>
    <name>vv::gui::PlanningDocks</name>
    <message>
        <source>Along the Path</source>
        <translation>Entlang des Pfads</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>Messungen</translation>
    </message>
</context>
<context>
    <name>vv::gui::PlanningState</name>
    <message>
        <source>Branch %1</source>
        <translation>Ast %1</translation>
    </message>
    <message>
        <source>Start (%1)</source>
        <translation>Anfang (%1)</translation>
    </message>
    <message>
        <source>End %1 (%2)</source>
        <translation>Ende %1 (%2)</translation>
    </message>
    <message>
        <source>End %1</source>
        <translation>Ende %1</translation>
    </message>
</context>
<context>
    <name>vv::gui::ReportDialog</name>
    <message>
        <source>Export Report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <source>&amp;Report (PDF):</source>
        <translation>&amp;Bericht (PDF):</translation>
    </message>
    <message>
        <source>Export report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation>PDF-Dokumente (*.pdf)</translation>
    </message>
    <message>
        <source>A4</source>
        <translation>A4</translation>
    </message>
    <message>
        <source>Letter</source>
        <translation>Letter</translation>
    </message>
    <message>
        <source>&amp;Paper:</source>
        <translation>&amp;Papier:</translation>
    </message>
    <message>
        <source>&amp;Findings:</source>
        <translation>Be&amp;fund:</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <source>A second image from a camera preset, below the view</source>
        <translation>Ein zweites Bild aus einer Kameravorgabe, unter der Ansicht</translation>
    </message>
    <message>
        <source>&amp;Second view:</source>
        <translation>&amp;Zweite Ansicht:</translation>
    </message>
    <message>
        <source>No parameter is shown on the vessels: the report has no statistics</source>
        <translation>Auf den Gefäßen wird kein Parameter angezeigt: der Bericht enthält keine Statistik</translation>
    </message>
    <message>
        <source>Statistics:</source>
        <translation>Statistik:</translation>
    </message>
    <message>
        <source>Area &amp;below</source>
        <translation>Fläche &amp;unter</translation>
    </message>
    <message>
        <source>Area abo&amp;ve</source>
        <translation>Fläche &amp;über</translation>
    </message>
    <message>
        <source>&amp;Anonymise the patient</source>
        <translation>Patienten &amp;anonymisieren</translation>
    </message>
    <message>
        <source>Print &quot;anonymised&quot; instead of the patient&apos;s data and leave the identifiers out of the DICOM exports</source>
        <translation>„anonymisiert“ statt der Patientendaten drucken und die Kennungen in den DICOM-Exporten weglassen</translation>
    </message>
    <message>
        <source>DICOM Secondary &amp;Capture</source>
        <translation>DICOM Secondary &amp;Capture</translation>
    </message>
    <message>
        <source>DICOM files (*.dcm)</source>
        <translation>DICOM-Dateien (*.dcm)</translation>
    </message>
    <message>
        <source>DICOM Encapsulated P&amp;DF</source>
        <translation>DICOM Encapsulated P&amp;DF</translation>
    </message>
    <message>
        <source>PNG &amp;image</source>
        <translation>PNG-B&amp;ild</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>There is no data on screen to report on.</source>
        <translation>Es werden keine Daten angezeigt, über die berichtet werden könnte.</translation>
    </message>
    <message>
        <source>PDF report</source>
        <translation>PDF-Bericht</translation>
    </message>
    <message>
        <source>Choose a file name for the %1.</source>
        <translation>Wählen Sie einen Dateinamen für: %1.</translation>
    </message>
    <message>
        <source>%1 is a folder; choose a file name for the %2.</source>
        <translation>%1 ist ein Ordner; wählen Sie einen Dateinamen für: %2.</translation>
    </message>
    <message>
        <source>%1: the folder %2 does not exist.</source>
        <translation>%1: der Ordner %2 existiert nicht.</translation>
    </message>
    <message>
        <source>%1 is chosen for two outputs.</source>
        <translation>%1 ist für zwei Ausgaben gewählt.</translation>
    </message>
    <message>
        <source>%1 is the data file shown: choose another name.</source>
        <translation>%1 ist die angezeigte Datendatei: wählen Sie einen anderen Namen.</translation>
    </message>
    <message>
        <source>Exporting the report %1</source>
        <translation>Bericht %1 wird exportiert</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <source>Findings, printed first, right after the patient</source>
        <translation>Befund, zuerst gedruckt, direkt nach dem Patienten</translation>
    </message>
    <message>
        <source>Meshes carry no patient data: enter the patient and study below to print them, or anonymised</source>
        <translation>Netze enthalten keine Patientendaten: Patient und Untersuchung unten eingeben, um sie (oder „anonymisiert“) zu drucken</translation>
    </message>
    <message>
        <source>Printed under the report&apos;s title; empty = no line</source>
        <translation>Unter dem Titel des Berichts gedruckt; leer = keine Zeile</translation>
    </message>
    <message>
        <source>Meshes carry no patient data: what you enter here is printed in the report and written to its DICOM exports</source>
        <translation>Netze enthalten keine Patientendaten: Was Sie hier eingeben, steht im Bericht und in seinen DICOM-Exporten</translation>
    </message>
    <message>
        <source>not given</source>
        <translation>nicht angegeben</translation>
    </message>
    <message>
        <source>female</source>
        <translation>weiblich</translation>
    </message>
    <message>
        <source>male</source>
        <translation>männlich</translation>
    </message>
    <message>
        <source>other</source>
        <translation>divers</translation>
    </message>
    <message>
        <source>The view as shown on screen</source>
        <translation>Die Ansicht wie auf dem Bildschirm</translation>
    </message>
    <message>
        <source>as shown on screen</source>
        <translation>wie auf dem Bildschirm</translation>
    </message>
    <message>
        <source>birth date</source>
        <translation>Geburtsdatum</translation>
    </message>
    <message>
        <source>study date</source>
        <translation>Untersuchungsdatum</translation>
    </message>
    <message>
        <source>Disclai&amp;mer:</source>
        <translation>&amp;Hinweis:</translation>
    </message>
    <message>
        <source>Patient and stud&amp;y</source>
        <translation>Patient und Unte&amp;rsuchung</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>Patient ID:</source>
        <translation>Patienten-ID:</translation>
    </message>
    <message>
        <source>Birth date:</source>
        <translation>Geburtsdatum:</translation>
    </message>
    <message>
        <source>Sex:</source>
        <translation>Geschlecht:</translation>
    </message>
    <message>
        <source>Study date:</source>
        <translation>Untersuchungsdatum:</translation>
    </message>
    <message>
        <source>Accession number:</source>
        <translation>Auftragsnummer:</translation>
    </message>
    <message>
        <source>Referring physician:</source>
        <translation>Überweisender Arzt:</translation>
    </message>
    <message>
        <source>&amp;Include it</source>
        <translation>Aufneh&amp;men</translation>
    </message>
    <message>
        <source>Slice with segmentation:</source>
        <translation>Schicht mit Segmentierung:</translation>
    </message>
    <message>
        <source>Family, Given</source>
        <translation>Nachname, Vorname</translation>
    </message>
    <message>
        <source>The %1 &quot;%2&quot; is not a date: enter it as %3 (for example %4).</source>
        <translation>„%2“ ist kein gültiges Datum (%1): bitte als %3 eingeben (zum Beispiel %4).</translation>
    </message>
    <message>
        <source>I&amp;nclude them</source>
        <translation>Ei&amp;nschließen</translation>
    </message>
    <message>
        <source>The sizing and branch tables, the diameter profile, the curved reformation and the cross-section at each landmark (Analysis panel)</source>
        <translation>Die Größen- und Asttabellen, das Durchmesserprofil, die gekrümmte Reformation und der Querschnitt an jeder Landmarke (Bereich Gefäßanalyse)</translation>
    </message>
    <message>
        <source>Measurements:</source>
        <translation>Messungen:</translation>
    </message>
    <message>
        <source>DICOM St&amp;ructured Report (measurements)</source>
        <translation>Strukturierter DICOM-Be&amp;richt (Messungen)</translation>
    </message>
    <message>
        <source>The measurements as a DICOM TID 1500 Measurement Report, read as data by a PACS and other viewers</source>
        <translation>Die Messungen als DICOM-TID-1500-Messbericht, den ein PACS und andere Betrachter als Daten lesen</translation>
    </message>
</context>
<context>
    <name>vv::gui::ScreenshotMode</name>
    <message>
        <source>timed out waiting for the data to be shown</source>
        <translation>Zeitüberschreitung beim Warten auf die Anzeige der Daten</translation>
    </message>
    <message>
        <source>the viewer&apos;s frame could not be read</source>
        <translation>das Bild der Ansicht konnte nicht gelesen werden</translation>
    </message>
    <message>
        <source>saved %1 (%2 x %3)</source>
        <translation>%1 gespeichert (%2 x %3)</translation>
    </message>
</context>
<context>
    <name>vv::gui::SendDialog</name>
    <message>
        <source>Send to PACS</source>
        <translation>An PACS senden</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>The view as an image (DICOM Secondary Capture)</source>
        <translation>Die Ansicht als Bild (DICOM Secondary Capture)</translation>
    </message>
    <message>
        <source>The PDF report (DICOM Encapsulated PDF)</source>
        <translation>Der PDF-Bericht (DICOM Encapsulated PDF)</translation>
    </message>
    <message>
        <source>PACS node:</source>
        <translation>PACS-Knoten:</translation>
    </message>
    <message>
        <source>Send:</source>
        <translation>Senden:</translation>
    </message>
    <message>
        <source>Instance</source>
        <translation>Instanz</translation>
    </message>
    <message>
        <source>Answer of the node</source>
        <translation>Antwort des Knotens</translation>
    </message>
    <message>
        <source>No PACS node is set up yet: add one under DICOM &gt; Preferences, then send.</source>
        <translation>Noch kein PACS-Knoten eingerichtet: Fügen Sie unter DICOM &gt; Einstellungen einen hinzu und senden Sie dann.</translation>
    </message>
    <message>
        <source>&amp;Send</source>
        <translation>&amp;Senden</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Sending the report to %1</source>
        <translation>Bericht wird an %1 gesendet</translation>
    </message>
    <message>
        <source>Sending to %1…</source>
        <translation>Senden an %1…</translation>
    </message>
    <message>
        <source>The report could not be made: %1</source>
        <translation>Der Bericht ließ sich nicht erstellen: %1</translation>
    </message>
    <message>
        <source>Cancelled: nothing more was sent.</source>
        <translation>Abgebrochen: Es wurde nichts mehr gesendet.</translation>
    </message>
    <message>
        <source>Making the report…</source>
        <translation>Bericht wird erstellt…</translation>
    </message>
    <message>
        <source>Report image (Secondary Capture)</source>
        <translation>Berichtsbild (Secondary Capture)</translation>
    </message>
    <message>
        <source>Report PDF (Encapsulated PDF)</source>
        <translation>Berichts-PDF (Encapsulated PDF)</translation>
    </message>
    <message>
        <source>Not sent</source>
        <translation>Nicht gesendet</translation>
    </message>
    <message>
        <source>Refused (status %1)</source>
        <translation>Abgelehnt (Status %1)</translation>
    </message>
    <message>
        <source>Accepted with a warning (status %1)</source>
        <translation>Mit Warnung angenommen (Status %1)</translation>
    </message>
    <message>
        <source>Accepted</source>
        <translation>Angenommen</translation>
    </message>
    <message>
        <source>%L1 of %L2 accepted by %3</source>
        <translation>%L1 von %L2 von %3 angenommen</translation>
    </message>
    <message>
        <source>Nothing was sent: %1 refused the connection. Nobody listens at that host and port, or a firewall blocks it.</source>
        <translation>Nichts wurde gesendet: %1 hat die Verbindung abgewiesen. Unter diesem Host und Port empfängt niemand, oder eine Firewall blockiert die Verbindung.</translation>
    </message>
    <message>
        <source>Nothing was sent: %1 rejected the association. It may not know our AE title %2, or the node&apos;s AE title is wrong.</source>
        <translation>Nichts wurde gesendet: %1 hat die Assoziation abgelehnt. Vielleicht kennt er unseren AE-Titel %2 nicht, oder der AE-Titel des Knotens ist falsch.</translation>
    </message>
    <message>
        <source>Nothing more was sent: %1 did not answer in time.</source>
        <translation>Es wurde nichts mehr gesendet: %1 hat nicht rechtzeitig geantwortet.</translation>
    </message>
    <message>
        <source>Nothing was sent: the TLS connection to %1 failed. Check the certificates of both sides.</source>
        <translation>Nichts wurde gesendet: Die TLS-Verbindung zu %1 ist fehlgeschlagen. Prüfen Sie die Zertifikate beider Seiten.</translation>
    </message>
    <message>
        <source>Segmentation (DICOM SEG)</source>
        <translation>Segmentierung (DICOM SEG)</translation>
    </message>
    <message>
        <source>The segmentation (DICOM SEG)</source>
        <translation>Die Segmentierung (DICOM SEG)</translation>
    </message>
    <message>
        <source>Only for data opened from DICOM and segmented</source>
        <translation>Nur für aus DICOM geöffnete und segmentierte Daten</translation>
    </message>
    <message>
        <source>the synthetic demo tree</source>
        <translation>der synthetische Demo-Gefäßbaum</translation>
    </message>
    <message>
        <source>the data on screen</source>
        <translation>die angezeigten Daten</translation>
    </message>
    <message>
        <source>Findings, printed first in the report</source>
        <translation>Befund, im Bericht zuerst gedruckt</translation>
    </message>
    <message>
        <source>A new report of the view, with the findings below</source>
        <translation>Ein neuer Bericht der Ansicht, mit dem Befund unten</translation>
    </message>
    <message>
        <source>Data:</source>
        <translation>Daten:</translation>
    </message>
    <message>
        <source>&amp;Report:</source>
        <translation>Be&amp;richt:</translation>
    </message>
    <message>
        <source>&amp;Findings:</source>
        <translation>Be&amp;fund:</translation>
    </message>
    <message>
        <source>The exported report %1, as it is</source>
        <translation>Der exportierte Bericht %1, unverändert</translation>
    </message>
    <message>
        <source>Other data was opened: the send of %1 was stopped; nothing more was sent.</source>
        <translation>Andere Daten wurden geöffnet: Das Senden von %1 wurde abgebrochen; nichts weiter wurde gesendet.</translation>
    </message>
    <message>
        <source>The exported report is sent with its own findings</source>
        <translation>Der exportierte Bericht wird mit seinem eigenen Befund gesendet</translation>
    </message>
    <message>
        <source>No temporary folder for the report could be made. Check the free space and the permissions of the temporary folder.</source>
        <translation>Für den Bericht konnte kein temporärer Ordner angelegt werden. Prüfen Sie den freien Speicherplatz und die Zugriffsrechte des temporären Ordners.</translation>
    </message>
    <message>
        <source>The transfer to %1 failed: the PACS closed the connection or reported a failure. The table says what was accepted before. Try again; if it keeps happening, ask the PACS administrator.</source>
        <translation>Die Übertragung an %1 ist fehlgeschlagen: Das PACS hat die Verbindung geschlossen oder einen Fehler gemeldet. Die Tabelle zeigt, was vorher angenommen wurde. Versuchen Sie es erneut; wenn es wieder geschieht, wenden Sie sich an die PACS-Administration.</translation>
    </message>
    <message>
        <source>Measurements (DICOM Structured Report)</source>
        <translation>Messungen (strukturierter DICOM-Bericht)</translation>
    </message>
    <message>
        <source>The measurements (DICOM Structured Report)</source>
        <translation>Die Messungen (strukturierter DICOM-Bericht)</translation>
    </message>
    <message>
        <source>Find the centrelines first (Analysis panel)</source>
        <translation>Finden Sie zuerst die Mittellinien (Bereich Gefäßanalyse)</translation>
    </message>
    <message>
        <source>The landmarks&apos; sections, the lengths, the sizing table and the branches as a TID 1500 Measurement Report, read as data by a PACS</source>
        <translation>Die Querschnitte der Landmarken, die Längen, die Größentabelle und die Äste als TID-1500-Messbericht, den ein PACS als Daten liest</translation>
    </message>
</context>
<context>
    <name>vv::gui::SeriesDialog</name>
    <message>
        <source>Choose a DICOM Series</source>
        <translation>DICOM-Serie auswählen</translation>
    </message>
    <message>
        <source>Patient / study / series</source>
        <translation>Patient / Studie / Serie</translation>
    </message>
    <message>
        <source>Modality</source>
        <translation>Modalität</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>Images</source>
        <translation>Bilder</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Größe</translation>
    </message>
    <message>
        <source>Patient %1</source>
        <translation>Patient %1</translation>
    </message>
    <message>
        <source>Patient: %1</source>
        <translation>Patient: %1</translation>
    </message>
    <message>
        <source>Study</source>
        <translation>Studie</translation>
    </message>
    <message>
        <source>Study %1</source>
        <translation>Studie %1</translation>
    </message>
    <message>
        <source>Series %1</source>
        <translation>Serie %1</translation>
    </message>
    <message>
        <source>Series</source>
        <translation>Serie</translation>
    </message>
    <message>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <source>%1 — cannot be loaded: %2</source>
        <translation>%1 — kann nicht geladen werden: %2</translation>
    </message>
    <message>
        <source>Skipped files: %1</source>
        <translation>Übersprungene Dateien: %1</translation>
    </message>
    <message>
        <source>Vessel segmentation</source>
        <translation>Gefäßsegmentierung</translation>
    </message>
    <message>
        <source>Default for the modality</source>
        <translation>Vorgabe der Modalität</translation>
    </message>
    <message>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <source>Threshold range:</source>
        <translation>Schwellwertbereich:</translation>
    </message>
    <message>
        <source>Keep this many of the largest connected components</source>
        <translation>So viele der größten zusammenhängenden Komponenten behalten</translation>
    </message>
    <message>
        <source>Components to keep:</source>
        <translation>Behaltene Komponenten:</translation>
    </message>
    <message>
        <source>Remove bone-like components</source>
        <translation>Knochenähnliche Komponenten entfernen</translation>
    </message>
    <message>
        <source>Load Series</source>
        <translation>Serie laden</translation>
    </message>
    <message>
        <source>CT angiography: 200 to 700 HU</source>
        <translation>CT-Angiographie: 200 bis 700 HU</translation>
    </message>
    <message>
        <source>%1 series %2</source>
        <translation>%1-Serie %2</translation>
    </message>
    <message>
        <source>DICOM series</source>
        <translation>DICOM-Serie</translation>
    </message>
    <message>
        <source>%1 series</source>
        <translation>%1-Serie</translation>
    </message>
    <message>
        <source>Enter both ends of the threshold range, or use the default for the modality</source>
        <translation>Beide Grenzen des Schwellenbereichs eingeben oder den Standard der Modalität verwenden</translation>
    </message>
    <message>
        <source>%1: from the image histogram when loaded</source>
        <translation>%1: beim Laden aus dem Bildhistogramm</translation>
    </message>
    <message>
        <source>This series</source>
        <translation>Diese Serie</translation>
    </message>
    <message>
        <source>Voxel spacing (mm)</source>
        <translation>Voxelabstand (mm)</translation>
    </message>
</context>
<context>
    <name>vv::gui::SliceTexts</name>
    <message>
        <source>Coronal</source>
        <translation>Koronal</translation>
    </message>
    <message>
        <source>Sagittal</source>
        <translation>Sagittal</translation>
    </message>
    <message>
        <source>Axial</source>
        <translation>Axial</translation>
    </message>
    <message>
        <source>CTA</source>
        <translation>CTA</translation>
    </message>
    <message>
        <source>MRA</source>
        <translation>MRA</translation>
    </message>
    <message>
        <source>Soft tissue</source>
        <translation>Weichteile</translation>
    </message>
    <message>
        <source>Bone</source>
        <translation>Knochen</translation>
    </message>
    <message>
        <source>Full range</source>
        <translation>Gesamter Wertebereich</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>W %1  L %2</source>
        <extracomment>W and L: the width and level (centre) of the grey-value window</extracomment>
        <translation>W %1  L %2</translation>
    </message>
</context>
<context>
    <name>vv::gui::SliceView</name>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>Wheel or Up/Down: slices · Ctrl+wheel or right-drag: zoom · Double-click: fit
Left-drag: window (right: wider, down: darker) · Middle or Shift+left-drag: pan
Click: show this point in every view</source>
        <translation>Mausrad oder Pfeil auf/ab: Schichten · Strg+Mausrad oder Ziehen rechts: zoomen · Doppelklick: einpassen
Ziehen links: Fenster (nach rechts breiter, nach unten dunkler) · Ziehen Mitte oder Umschalt+links: verschieben
Klick: diesen Punkt in allen Ansichten zeigen</translation>
    </message>
</context>
<context>
    <name>vv::gui::SliceWorkspace</name>
    <message>
        <source>S&amp;lices</source>
        <translation>Sc&amp;hichtbilder</translation>
    </message>
    <message>
        <source>&amp;3-D Only</source>
        <translation>Nur &amp;3-D</translation>
    </message>
    <message>
        <source>3-D and &amp;Three Slices</source>
        <translation>3-D und &amp;drei Schichten</translation>
    </message>
    <message>
        <source>Large &amp;Axial Slice</source>
        <translation>Große &amp;axiale Schicht</translation>
    </message>
    <message>
        <source>Large &amp;Coronal Slice</source>
        <translation>Große &amp;koronale Schicht</translation>
    </message>
    <message>
        <source>Large &amp;Sagittal Slice</source>
        <translation>Große &amp;sagittale Schicht</translation>
    </message>
    <message>
        <source>&amp;Window</source>
        <translation>&amp;Fenster</translation>
    </message>
    <message>
        <source>Segmentation &amp;Fill</source>
        <translation>Segmentierung als &amp;Fläche</translation>
    </message>
    <message>
        <source>Segmentation &amp;Outline</source>
        <translation>Segmentierung als &amp;Umriss</translation>
    </message>
    <message>
        <source>The segmented voxels tinted in their label colour</source>
        <translation>Die segmentierten Voxel in der Farbe ihres Labels eingefärbt</translation>
    </message>
    <message>
        <source>The edge of the segmentation drawn in its label colour</source>
        <translation>Der Rand der Segmentierung in der Farbe ihres Labels</translation>
    </message>
</context>
<context>
    <name>vv::gui::StoreLeases</name>
    <message>
        <source>This study is no longer in the local study store.</source>
        <translation>Diese Studie ist nicht mehr im lokalen Studienspeicher.</translation>
    </message>
    <message>
        <source>The study cannot be opened now: the local study store is busy or cannot be read. Try again in a moment.</source>
        <translation>Die Studie lässt sich jetzt nicht öffnen: Der lokale Studienspeicher ist belegt oder lässt sich nicht lesen. Versuchen Sie es gleich noch einmal.</translation>
    </message>
</context>
<context>
    <name>vv::gui::StudyAnalysisDialog</name>
    <message>
        <source>&amp;Analyse</source>
        <translation>&amp;Auswerten</translation>
    </message>
    <message>
        <source>&amp;Open the PDF</source>
        <translation>PDF ö&amp;ffnen</translation>
    </message>
    <message>
        <source>Analyse Depth-Judgement Study</source>
        <translation>Tiefenurteil-Studie auswerten</translation>
    </message>
    <message>
        <source>A&amp;dd…</source>
        <translation>&amp;Hinzufügen…</translation>
    </message>
    <message>
        <source>Re&amp;move</source>
        <translation>&amp;Entfernen</translation>
    </message>
    <message>
        <source>Results &amp;files:</source>
        <translation>Ergebnis&amp;dateien:</translation>
    </message>
    <message>
        <source>Results files of the study</source>
        <translation>Ergebnisdateien der Studie</translation>
    </message>
    <message>
        <source>Results (*.csv)</source>
        <translation>Ergebnisse (*.csv)</translation>
    </message>
    <message>
        <source>Bonferroni</source>
        <translation>Bonferroni</translation>
    </message>
    <message>
        <source>Holm</source>
        <translation>Holm</translation>
    </message>
    <message>
        <source>Post-hoc &amp;correction:</source>
        <translation>Post-hoc-&amp;Korrektur:</translation>
    </message>
    <message>
        <source>Significance &amp;level α:</source>
        <translation>Signifikanz&amp;niveau α:</translation>
    </message>
    <message>
        <source>A4</source>
        <translation>A4</translation>
    </message>
    <message>
        <source>Letter</source>
        <translation>Letter</translation>
    </message>
    <message>
        <source>&amp;Paper:</source>
        <translation>&amp;Papier:</translation>
    </message>
    <message>
        <source>PDF f&amp;ile:</source>
        <translation>PDF-Da&amp;tei:</translation>
    </message>
    <message>
        <source>The study&apos;s PDF</source>
        <translation>PDF der Studie</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keiner</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>Folder for the tables</source>
        <translation>Ordner für die Tabellen</translation>
    </message>
    <message>
        <source>&amp;Tables (CSV) in:</source>
        <translation>Tabellen (CSV) &amp;in:</translation>
    </message>
    <message>
        <source>Add the study&apos;s results files.</source>
        <translation>Fügen Sie die Ergebnisdateien der Studie hinzu.</translation>
    </message>
    <message>
        <source>Give the PDF a file name ending in .pdf.</source>
        <translation>Geben Sie dem PDF einen Dateinamen, der auf .pdf endet.</translation>
    </message>
    <message>
        <source>Analysing…</source>
        <translation>Wird ausgewertet…</translation>
    </message>
    <message>
        <source>Written: %1</source>
        <translation>Geschrieben: %1</translation>
    </message>
</context>
<context>
    <name>vv::gui::StudyDate</name>
    <message>
        <source>yyyy-MM-dd</source>
        <extracomment>Date format of dates on screen (QDate::toString), as the report&apos;s: dd.MM.yyyy in German.</extracomment>
        <translation>dd.MM.yyyy</translation>
    </message>
    <message>
        <source>YYYY-MM-DD</source>
        <extracomment>How a date is typed, in the letters of the language: the date format of dates on screen (&quot;yyyy-MM-dd&quot; above) with Y = year, M = month, D = day; TT.MM.JJJJ in German.</extracomment>
        <translation>TT.MM.JJJJ</translation>
    </message>
</context>
<context>
    <name>vv::gui::StudyProblem</name>
    <message>
        <source>Details (in English): %1</source>
        <translation>Details (auf Englisch): %1</translation>
    </message>
    <message>
        <source>The study&apos;s answers cannot be analysed as they are.</source>
        <translation>Die Antworten der Studie können so nicht ausgewertet werden.</translation>
    </message>
    <message>
        <source>%1 does not hold what the study needs.</source>
        <translation>%1 enthält nicht, was die Studie braucht.</translation>
    </message>
</context>
<context>
    <name>vv::gui::StudyRunDialog</name>
    <message>
        <source>Run Depth-Judgement Study</source>
        <translation>Tiefenurteil-Studie durchführen</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>Study folder (made by vesselview-cli study make)</source>
        <translation>Studienordner (von vesselview-cli study make erstellt)</translation>
    </message>
    <message>
        <source>&amp;Study folder:</source>
        <translation>&amp;Studienordner:</translation>
    </message>
    <message>
        <source>&amp;Results file:</source>
        <translation>&amp;Ergebnisdatei:</translation>
    </message>
    <message>
        <source>Results file</source>
        <translation>Ergebnisdatei</translation>
    </message>
    <message>
        <source>Results (*.csv)</source>
        <translation>Ergebnisse (*.csv)</translation>
    </message>
    <message>
        <source>e.g. P07</source>
        <translation>z. B. P07</translation>
    </message>
    <message>
        <source>&amp;Participant:</source>
        <translation>&amp;Teilnehmer:</translation>
    </message>
    <message>
        <source>&amp;Training images first, with feedback</source>
        <translation>Zuerst Ü&amp;bungsbilder, mit Rückmeldung</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keiner</translation>
    </message>
    <message>
        <source>&amp;Countdown before each image:</source>
        <translation>&amp;Countdown vor jedem Bild:</translation>
    </message>
    <message>
        <source>no breaks</source>
        <translation>keine Pausen</translation>
    </message>
    <message>
        <source>every </source>
        <translation>alle </translation>
    </message>
    <message>
        <source> images</source>
        <translation> Bilder</translation>
    </message>
    <message>
        <source>&amp;Break:</source>
        <translation>&amp;Pause:</translation>
    </message>
    <message>
        <source>Choose the folder that vesselview-cli study make wrote.</source>
        <translation>Wählen Sie den Ordner, den vesselview-cli study make geschrieben hat.</translation>
    </message>
    <message>
        <source>Type the participant&apos;s id.</source>
        <translation>Geben Sie die Kennung des Teilnehmers ein.</translation>
    </message>
    <message>
        <source>A new participant (%1).</source>
        <translation>Ein neuer Teilnehmer (%1).</translation>
    </message>
    <message>
        <source>%1 has answered all %2 images.</source>
        <translation>%1 hat alle %2 Bilder beantwortet.</translation>
    </message>
    <message>
        <source>%1 has answered %2 of %3 images; the run goes on from image %4 (%5).</source>
        <translation>%1 hat %2 von %3 Bildern beantwortet; der Durchgang geht bei Bild %4 weiter (%5).</translation>
    </message>
    <message>
        <source>St&amp;art</source>
        <translation>St&amp;arten</translation>
    </message>
    <message>
        <source>%1 images in %2 conditions from %3; %4 training images.</source>
        <translation>%1 Bilder in %2 Bedingungen aus %3; %4 Übungsbilder.</translation>
    </message>
    <message numerus="yes">
        <source>%n scene(s)</source>
        <translation>
            <numerusform>%n Szene</numerusform>
            <numerusform>%n Szenen</numerusform>
        </translation>
    </message>
    <message>
        <source>order %1: the Latin square&apos;s row %2 of %3</source>
        <translation>Reihenfolge %1: Zeile %2 von %3 des lateinischen Quadrats</translation>
    </message>
</context>
<context>
    <name>vv::gui::StudyRunnerWidget</name>
    <message>
        <source>Depth-judgement study</source>
        <translation>Tiefenurteil-Studie</translation>
    </message>
    <message>
        <source>The image %1 cannot be read. The run stops; the answers given so far are saved.</source>
        <translation>Das Bild %1 kann nicht gelesen werden. Der Durchgang endet; die bisherigen Antworten sind gespeichert.</translation>
    </message>
    <message>
        <source>Stop the run? The answers given so far are saved; the same participant id goes on from here.</source>
        <translation>Den Durchgang beenden? Die bisherigen Antworten sind gespeichert; mit derselben Teilnehmerkennung geht es hier weiter.</translation>
    </message>
    <message>
        <source>Press the space bar to go on.</source>
        <translation>Drücken Sie die Leertaste, um fortzufahren.</translation>
    </message>
    <message>
        <source>Which marker is closer to you?</source>
        <translation>Welche Markierung ist näher bei Ihnen?</translation>
    </message>
    <message>
        <source>Each image shows vessels with two markers. Press F (or the left arrow) when the left marker is closer to you, J (or the right arrow) when the right one is. Answer as quickly as you can while being sure.

A countdown comes before each image; between images this grey screen waits for the space bar.</source>
        <translation>Jedes Bild zeigt Gefäße mit zwei Markierungen. Drücken Sie F (oder den Pfeil nach links), wenn die linke Markierung näher bei Ihnen ist, J (oder den Pfeil nach rechts), wenn es die rechte ist. Antworten Sie so schnell Sie können, aber sicher.

Vor jedem Bild läuft ein Countdown; zwischen den Bildern wartet dieser graue Bildschirm auf die Leertaste.</translation>
    </message>
    <message>
        <source>You begin with training images and are told after each whether your answer was right. Go on with them until you feel familiar with the task, then press Enter.</source>
        <translation>Sie beginnen mit Übungsbildern und erfahren nach jedem, ob Ihre Antwort richtig war. Üben Sie, bis Sie mit der Aufgabe vertraut sind, und drücken Sie dann die Eingabetaste.</translation>
    </message>
    <message>
        <source>Welcome back: %1 of %2 images are answered; the study goes on from there.</source>
        <translation>Willkommen zurück: %1 von %2 Bildern sind beantwortet; die Studie geht dort weiter.</translation>
    </message>
    <message>
        <source>Press the space bar to begin.</source>
        <translation>Drücken Sie die Leertaste, um zu beginnen.</translation>
    </message>
    <message>
        <source>Image %1 of %2</source>
        <translation>Bild %1 von %2</translation>
    </message>
    <message>
        <source>Correct</source>
        <translation>Richtig</translation>
    </message>
    <message>
        <source>Not correct</source>
        <translation>Nicht richtig</translation>
    </message>
    <message>
        <source>The left marker was closer.</source>
        <translation>Die linke Markierung war näher.</translation>
    </message>
    <message>
        <source>The right marker was closer.</source>
        <translation>Die rechte Markierung war näher.</translation>
    </message>
    <message>
        <source>Space bar: another training image. Enter: begin the study.</source>
        <translation>Leertaste: ein weiteres Übungsbild. Eingabetaste: die Studie beginnen.</translation>
    </message>
    <message>
        <source>The study begins</source>
        <translation>Die Studie beginnt</translation>
    </message>
    <message>
        <source>From now on you are not told whether an answer was right. %1 images.</source>
        <translation>Ab jetzt erfahren Sie nicht mehr, ob eine Antwort richtig war. %1 Bilder.</translation>
    </message>
    <message>
        <source>Break</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Take a rest: %1 of %2 images are done.</source>
        <translation>Ruhen Sie sich aus: %1 von %2 Bildern sind geschafft.</translation>
    </message>
    <message>
        <source>Press the space bar when you are ready.</source>
        <translation>Drücken Sie die Leertaste, wenn Sie bereit sind.</translation>
    </message>
    <message>
        <source>Thank you</source>
        <translation>Vielen Dank</translation>
    </message>
    <message>
        <source>The study is complete and your answers are saved. The person running the study closes this screen with Escape.</source>
        <translation>Die Studie ist abgeschlossen, Ihre Antworten sind gespeichert. Die Studienleitung schließt diesen Bildschirm mit Escape.</translation>
    </message>
    <message>
        <source>The answer cannot be saved; the run stops, and the answers saved before stay in the file.</source>
        <translation>Die Antwort kann nicht gespeichert werden; der Durchgang endet, die zuvor gespeicherten Antworten bleiben in der Datei.</translation>
    </message>
</context>
<context>
    <name>vv::gui::TlsFilesBox</name>
    <message>
        <source>Trusted &amp;CA certificate:</source>
        <translation>Vertrauenswürdiges &amp;CA-Zertifikat:</translation>
    </message>
    <message>
        <source>Our c&amp;ertificate (optional):</source>
        <translation>Unser &amp;Zertifikat (optional):</translation>
    </message>
    <message>
        <source>Our c&amp;ertificate:</source>
        <translation>Unser &amp;Zertifikat:</translation>
    </message>
    <message>
        <source>Our &amp;key (with the certificate):</source>
        <translation>Unser &amp;Schlüssel (zum Zertifikat):</translation>
    </message>
    <message>
        <source>Our &amp;key:</source>
        <translation>Unser &amp;Schlüssel:</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>Choose a PEM file</source>
        <translation>PEM-Datei wählen</translation>
    </message>
    <message>
        <source>PEM files (*.pem *.crt *.key);;All files (*)</source>
        <translation>PEM-Dateien (*.pem *.crt *.key);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Trusted CA certificate: TLS needs the certificate of the CA that signed the PACS&apos;s certificate.</source>
        <translation>Vertrauenswürdiges CA-Zertifikat: TLS braucht das Zertifikat der CA, die das Zertifikat des PACS signiert hat.</translation>
    </message>
    <message>
        <source>Trusted CA certificate: the listener needs the certificate of the CA that signed the certificates of the nodes sending to us.</source>
        <translation>Vertrauenswürdiges CA-Zertifikat: Der Empfang braucht das Zertifikat der CA, die die Zertifikate der an uns sendenden Knoten signiert hat.</translation>
    </message>
    <message>
        <source>Our certificate and key: the listener needs both to speak TLS.</source>
        <translation>Unser Zertifikat und Schlüssel: Für TLS braucht der Empfang beide.</translation>
    </message>
    <message>
        <source>Our certificate and key: give both or neither.</source>
        <translation>Unser Zertifikat und Schlüssel: Geben Sie beide oder keines an.</translation>
    </message>
</context>
<context>
    <name>vv::gui::ViewerWidget</name>
    <message>
        <source>No OpenGL context can be created here (platform &apos;%1&apos;). VesselView needs OpenGL 4.1 (core profile): update the graphics driver, or run with Mesa&apos;s software renderer (LIBGL_ALWAYS_SOFTWARE=1).</source>
        <translation>Hier lässt sich kein OpenGL-Kontext erzeugen (Plattform „%1“). VesselView benötigt OpenGL 4.1 (Core Profile): Grafiktreiber aktualisieren oder mit dem Software-Renderer von Mesa starten (LIBGL_ALWAYS_SOFTWARE=1).</translation>
    </message>
    <message>
        <source>VesselView needs OpenGL 4.1 (core profile); this system offers %1 %2.%3. Update the graphics driver, or run with Mesa&apos;s software renderer (LIBGL_ALWAYS_SOFTWARE=1).</source>
        <translation>VesselView benötigt OpenGL 4.1 (Core Profile); dieses System bietet %1 %2.%3. Grafiktreiber aktualisieren oder mit dem Software-Renderer von Mesa starten (LIBGL_ALWAYS_SOFTWARE=1).</translation>
    </message>
    <message>
        <source>OpenGL could not be initialised: VesselView needs OpenGL 4.1 (core profile). Update the graphics driver, or run with Mesa&apos;s software renderer (LIBGL_ALWAYS_SOFTWARE=1).</source>
        <translation>OpenGL konnte nicht initialisiert werden: VesselView benötigt OpenGL 4.1 (Core Profile). Grafiktreiber aktualisieren oder mit dem Software-Renderer von Mesa starten (LIBGL_ALWAYS_SOFTWARE=1).</translation>
    </message>
    <message>
        <source>OpenGL could not be initialised: no valid OpenGL context.</source>
        <translation>OpenGL konnte nicht initialisiert werden: kein gültiger OpenGL-Kontext.</translation>
    </message>
    <message>
        <source>VesselView needs OpenGL 4.1 (core profile); this system offers OpenGL %1.%2.

%3

Update the graphics driver, or run with Mesa&apos;s software renderer (LIBGL_ALWAYS_SOFTWARE=1).</source>
        <translation>VesselView benötigt OpenGL 4.1 (Core Profile); dieses System bietet OpenGL %1.%2.

%3

Grafiktreiber aktualisieren oder mit dem Software-Renderer von Mesa starten (LIBGL_ALWAYS_SOFTWARE=1).</translation>
    </message>
    <message>
        <source>OpenGL is not available.</source>
        <translation>OpenGL ist nicht verfügbar.</translation>
    </message>
    <message>
        <source>Drawing failed: %1</source>
        <translation>Zeichnen fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Object %1</source>
        <translation>Objekt %1</translation>
    </message>
    <message>
        <source>no data</source>
        <translation>keine Daten</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: %2 %3</source>
        <translation>%1: %2 %3</translation>
    </message>
    <message>
        <source>Left-drag: rotate · Right/middle or Shift+left-drag: pan · Wheel: zoom
R: reset view · F: fit to data · Ctrl+click: measure</source>
        <translation>Ziehen links: drehen · Ziehen rechts/Mitte oder Umschalt+links: verschieben · Mausrad: zoomen
R: Ansicht zurücksetzen · F: an Daten anpassen · Strg+Klick: messen</translation>
    </message>
    <message>
        <source>Volume (iso-surface at %1)</source>
        <translation>Volumen (Isofläche bei %1)</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>%1 %2 (%3)</source>
        <translation>%1 %2 (%3)</translation>
    </message>
    <message>
        <source>%1: %2 mm</source>
        <translation>%1: %2 mm</translation>
    </message>
</context>
<context>
    <name>vv::gui::panels::AnalysisPanel</name>
    <message>
        <source>Find Centrelines</source>
        <translation>Mittellinien finden</translation>
    </message>
    <message>
        <source>Compute the centrelines of the shown surface, their cross-sections and stenoses</source>
        <translation>Berechnet die Mittellinien der gezeigten Oberfläche, ihre Querschnitte und Stenosen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Branch</source>
        <translation>Ast</translation>
    </message>
    <message>
        <source>Stenosis</source>
        <translation>Stenose</translation>
    </message>
    <message>
        <source>The narrowest point of each branch against its reference diameter (hover a row for how the reference was found)</source>
        <translation>Die engste Stelle jedes Asts gegen seinen Referenzdurchmesser (wie die Referenz gefunden wurde: Maus auf die Zeile)</translation>
    </message>
    <message>
        <source>Reference:</source>
        <translation>Referenz:</translation>
    </message>
    <message>
        <source>Proximal</source>
        <translation>Proximal</translation>
    </message>
    <message>
        <source>Grade the branch at the cursor against the diameter here (proximal reference) and at its distal reference</source>
        <translation>Den Ast am Cursor gegen den Durchmesser hier (proximale Referenz) und an seiner distalen Referenz graduieren</translation>
    </message>
    <message>
        <source>Distal</source>
        <translation>Distal</translation>
    </message>
    <message>
        <source>Grade the branch at the cursor against the diameter here (distal reference) and at its proximal reference</source>
        <translation>Den Ast am Cursor gegen den Durchmesser hier (distale Referenz) und an seiner proximalen Referenz graduieren</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>Grade the branch at the cursor against healthy stretches either side of its narrowest point</source>
        <translation>Den Ast am Cursor gegen gesunde Abschnitte beiderseits seiner engsten Stelle graduieren</translation>
    </message>
    <message>
        <source>The branch cannot be graded against a reference here</source>
        <translation>Der Ast kann hier nicht gegen eine Referenz graduiert werden</translation>
    </message>
    <message>
        <source>Path from:</source>
        <translation>Pfad von:</translation>
    </message>
    <message>
        <source>to:</source>
        <translation>bis:</translation>
    </message>
    <message>
        <source>Pick on Vessel</source>
        <translation>Am Gefäß wählen</translation>
    </message>
    <message>
        <source>Click a vessel in the 3-D view: the cursor moves to the path there</source>
        <translation>Klicken Sie in der 3D-Ansicht auf ein Gefäß: Der Cursor springt dort auf den Pfad</translation>
    </message>
    <message>
        <source>A path needs two different ends</source>
        <translation>Ein Pfad braucht zwei verschiedene Enden</translation>
    </message>
    <message>
        <source>Free name</source>
        <translation>Freier Name</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Place at Cursor</source>
        <translation>Am Cursor setzen</translation>
    </message>
    <message>
        <source>Place the landmark at the cursor (Insert in the diameter profile)</source>
        <translation>Die Landmarke am Cursor setzen (Einfg im Durchmesserprofil)</translation>
    </message>
    <message>
        <source>Landmark:</source>
        <translation>Landmarke:</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>Landmark</source>
        <translation>Landmarke</translation>
    </message>
    <message>
        <source>Select a landmark to move it: Ctrl+Left / Ctrl+Right in the diameter profile, or drag its line there</source>
        <translation>Wählen Sie eine Landmarke, um sie zu verschieben: Strg+Links / Strg+Rechts im Durchmesserprofil, oder ziehen Sie dort ihre Linie</translation>
    </message>
    <message>
        <source>Move to Cursor</source>
        <translation>Zum Cursor</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Save Measurements…</source>
        <translation>Messungen speichern…</translation>
    </message>
    <message>
        <source>A measurement file for the report (vesselview-cli report --measurements) and other programs</source>
        <translation>Eine Messdatei für den Bericht (vesselview-cli report --measurements) und andere Programme</translation>
    </message>
    <message>
        <source>Export Sections…</source>
        <translation>Querschnitte exportieren…</translation>
    </message>
    <message>
        <source>The cross-sections along the path as CSV</source>
        <translation>Die Querschnitte entlang des Pfads als CSV</translation>
    </message>
    <message>
        <source>A free landmark needs a name</source>
        <translation>Eine freie Landmarke braucht einen Namen</translation>
    </message>
    <message>
        <source>Open a vessel surface first</source>
        <translation>Öffnen Sie zuerst eine Gefäßoberfläche</translation>
    </message>
    <message>
        <source>Find the centrelines to measure along the vessels.</source>
        <translation>Finden Sie die Mittellinien, um entlang der Gefäße zu messen.</translation>
    </message>
    <message>
        <source>%1 saved item(s) do not fit the centrelines found and were left out</source>
        <translation>%1 gespeicherte Einträge passen nicht zu den gefundenen Mittellinien und wurden weggelassen</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Wird gestartet…</translation>
    </message>
    <message>
        <source>Branches: %1; centreline: %2.</source>
        <translation>Äste: %1; Mittellinie: %2.</translation>
    </message>
    <message>
        <source>Reference %1: %2</source>
        <translation>Referenz %1: %2</translation>
    </message>
    <message>
        <source>not on the path</source>
        <translation>nicht auf dem Pfad</translation>
    </message>
    <message>
        <source>Cursor at %1 along the path (%2).</source>
        <translation>Cursor bei %1 entlang des Pfads (%2).</translation>
    </message>
    <message>
        <source>Diameter %1 (minimum %2, maximum %3), area %4</source>
        <translation>Durchmesser %1 (Minimum %2, Maximum %3), Fläche %4</translation>
    </message>
    <message>
        <source>No section here (an end or a junction)</source>
        <translation>Hier kein Querschnitt (ein Ende oder eine Verzweigung)</translation>
    </message>
    <message>
        <source>Find the centrelines first.</source>
        <translation>Finden Sie zuerst die Mittellinien.</translation>
    </message>
    <message>
        <source>Save Measurements</source>
        <translation>Messungen speichern</translation>
    </message>
    <message>
        <source>Measurement files (*.json)</source>
        <translation>Messdateien (*.json)</translation>
    </message>
    <message>
        <source>Measurements saved to %1</source>
        <translation>Messungen gespeichert in %1</translation>
    </message>
    <message>
        <source>Export Sections</source>
        <translation>Querschnitte exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Sections exported to %1</source>
        <translation>Querschnitte exportiert nach %1</translation>
    </message>
    <message>
        <source>No vessel of the path under the mouse</source>
        <translation>Kein Gefäß des Pfads unter der Maus</translation>
    </message>
    <message>
        <source>Length (mm)</source>
        <translation>Länge (mm)</translation>
    </message>
    <message>
        <source>Ø (mm)</source>
        <translation>Ø (mm)</translation>
    </message>
    <message>
        <source>Double-click a name to rename the branch (the name goes into reports). Ø: the narrowest and the widest equivalent diameter, 2√(area/π), outside the ends of the branch.</source>
        <translation>Doppelklick auf einen Namen benennt den Ast um (der Name erscheint in Berichten). Ø: der engste und der weiteste Äquivalentdurchmesser, 2√(Fläche/π), außerhalb der Enden des Asts.</translation>
    </message>
    <message>
        <source>Ø / area (%)</source>
        <translation>Ø / Fläche (%)</translation>
    </message>
    <message>
        <source>At (mm)</source>
        <translation>Bei (mm)</translation>
    </message>
    <message>
        <source>Pick Ends</source>
        <translation>Enden wählen</translation>
    </message>
    <message>
        <source>Click the vessel where the centrelines start (first click) and where they end (each further click); Find Centrelines then uses them instead of the automatic ends</source>
        <translation>Klicken Sie auf das Gefäß, wo die Mittellinien beginnen (erster Klick) und wo sie enden (jeder weitere Klick); Mittellinien finden nimmt dann diese statt der automatisch gefundenen Enden</translation>
    </message>
    <message>
        <source>Automatic Ends</source>
        <translation>Enden automatisch</translation>
    </message>
    <message>
        <source>Forget the picked ends: the open ends and tips are found</source>
        <translation>Die gewählten Enden vergessen: Die offenen Enden und Spitzen werden gefunden</translation>
    </message>
    <message>
        <source>Path highlighted</source>
        <translation>Pfad hervorgehoben</translation>
    </message>
    <message>
        <source>By branch</source>
        <translation>Nach Ast</translation>
    </message>
    <message>
        <source>By diameter</source>
        <translation>Nach Durchmesser</translation>
    </message>
    <message>
        <source>How the centrelines are coloured in the 3-D view</source>
        <translation>Wie die Mittellinien in der 3D-Ansicht gefärbt sind</translation>
    </message>
    <message>
        <source>Lines:</source>
        <translation>Linien:</translation>
    </message>
    <message>
        <source>Ends: found automatically</source>
        <translation>Enden: automatisch gefunden</translation>
    </message>
    <message>
        <source>Ends: picked, a start and %1 more</source>
        <translation>Enden: gewählt, ein Anfang und %1 weitere</translation>
    </message>
    <message>
        <source>No vessel under the mouse: click on a vessel</source>
        <translation>Kein Gefäß unter der Maus: ein Gefäß anklicken</translation>
    </message>
</context>
<context>
    <name>vv::gui::panels::ArrayValuesWidget</name>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>Continuous</source>
        <translation>Kontinuierlich</translation>
    </message>
    <message>
        <source>Categories (labels)</source>
        <translation>Kategorien (Labels)</translation>
    </message>
    <message>
        <source>The labels of the array and their colours, as the legend shows them</source>
        <translation>Die Labels des Datenfelds und ihre Farben, wie die Legende sie zeigt</translation>
    </message>
    <message>
        <source>Continuous: the values are measurements, shown through the colour map. Categories: the values are labels (segment, branch or group ids), one colour each. Automatic: categories for whole-numbered arrays with few distinct values</source>
        <translation>Kontinuierlich: Die Werte sind Messwerte und werden über die Farbtabelle dargestellt. Kategorien: Die Werte sind Labels (Segment-, Ast- oder Gruppen-IDs), jedes in einer eigenen Farbe. Automatisch: Kategorien für ganzzahlige Datenfelder mit wenigen verschiedenen Werten</translation>
    </message>
    <message>
        <source>Choose an array to colour the vessels with</source>
        <translation>Ein Datenfeld zum Einfärben der Gefäße wählen</translation>
    </message>
</context>
<context>
    <name>vv::gui::panels::DataPanel</name>
    <message>
        <source>Object / array</source>
        <translation>Objekt / Datenfeld</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Eckpunkte</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Dreiecke</translation>
    </message>
    <message>
        <source>No data loaded</source>
        <translation>Keine Daten geladen</translation>
    </message>
    <message>
        <source>Generated</source>
        <translation>Erzeugt</translation>
    </message>
    <message>
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
    <message>
        <source>no data</source>
        <translation>keine Daten</translation>
    </message>
    <message>
        <source>Point array (range of its finite values)</source>
        <translation>Punktdatenfeld (Bereich seiner endlichen Werte)</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <source>Array</source>
        <translation>Datenfeld</translation>
    </message>
    <message>
        <source>Colour of %1</source>
        <translation>Farbe von %1</translation>
    </message>
    <message>
        <source>Scene array</source>
        <translation>Datenfeld der Szene</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Keines</translation>
    </message>
    <message>
        <source>The object is hidden: tick it to show it</source>
        <translation>Das Objekt ist ausgeblendet: zum Anzeigen ankreuzen</translation>
    </message>
    <message>
        <source>Material colour of this object when no array colours it</source>
        <translation>Materialfarbe dieses Objekts, wenn kein Datenfeld es einfärbt</translation>
    </message>
    <message>
        <source>An array colours this object; choose the array None to use a material colour</source>
        <translation>Ein Datenfeld färbt dieses Objekt ein; für eine Materialfarbe das Datenfeld „Keines“ wählen</translation>
    </message>
    <message>
        <source>Below 100 % the surface and the VSS behind it show through; 0 % hides the object</source>
        <translation>Unter 100 % scheinen die Oberfläche und die VSS dahinter durch; 0 % blendet das Objekt aus</translation>
    </message>
    <message>
        <source>The array this object shows: the scene&apos;s (Functional panel), none, or one of its own point arrays</source>
        <translation>Das Datenfeld, das dieses Objekt zeigt: das der Szene (Bereich Funktionelle Parameter), keines oder eines seiner eigenen Punktdatenfelder</translation>
    </message>
    <message>
        <source>This object has no point arrays</source>
        <translation>Dieses Objekt hat keine Punktdatenfelder</translation>
    </message>
    <message>
        <source>DICOM Series…</source>
        <translation>DICOM-Serien…</translation>
    </message>
    <message>
        <source>Choose a DICOM folder and browse its patients, studies and series</source>
        <translation>Einen DICOM-Ordner wählen und seine Patienten, Studien und Serien durchsuchen</translation>
    </message>
    <message>
        <source>Browse the patients, studies and series of %1 and load another series</source>
        <translation>Patienten, Studien und Serien von %1 durchsuchen und eine andere Serie laden</translation>
    </message>
    <message>
        <source>%1: %2 vertices, %3 triangles</source>
        <translation>%1: %2 Eckpunkte, %3 Dreiecke</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>vv::gui::panels::DisplayPanel</name>
    <message>
        <source>Dark grey</source>
        <translation>Dunkelgrau</translation>
    </message>
    <message>
        <source>Black</source>
        <translation>Schwarz</translation>
    </message>
    <message>
        <source>Mid grey</source>
        <translation>Mittelgrau</translation>
    </message>
    <message>
        <source>White</source>
        <translation>Weiß</translation>
    </message>
    <message>
        <source>A depth cue on the vessels themselves, for comparison with the VSS</source>
        <translation>Ein Tiefenhinweis auf den Gefäßen selbst, zum Vergleich mit der VSS</translation>
    </message>
    <message>
        <source>Colour behind the vessels and the VSS</source>
        <translation>Farbe hinter den Gefäßen und der VSS</translation>
    </message>
    <message>
        <source>Custom…</source>
        <translation>Benutzerdefiniert…</translation>
    </message>
    <message>
        <source>Camera:</source>
        <translation>Kamera:</translation>
    </message>
    <message>
        <source>Depth and parameter legends over the view</source>
        <translation>Tiefen- und Parameterlegenden über der Ansicht</translation>
    </message>
    <message>
        <source>Performance overlay</source>
        <translation>Leistungsanzeige</translation>
    </message>
    <message>
        <source>The last frame&apos;s render passes and their CPU time in ms</source>
        <translation>Die Render-Durchläufe des letzten Bildes und ihre CPU-Zeit in ms</translation>
    </message>
    <message>
        <source>Far</source>
        <translation>Fern</translation>
    </message>
    <message>
        <source>Medium</source>
        <translation>Mittel</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Nah</translation>
    </message>
    <message>
        <source>Anterior</source>
        <translation>Anterior</translation>
    </message>
    <message>
        <source>Posterior</source>
        <translation>Posterior</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Links</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Rechts</translation>
    </message>
    <message>
        <source>Superior</source>
        <translation>Superior</translation>
    </message>
    <message>
        <source>Inferior</source>
        <translation>Inferior</translation>
    </message>
    <message>
        <source>Background colour</source>
        <translation>Hintergrundfarbe</translation>
    </message>
    <message>
        <source>Vessel colour</source>
        <translation>Gefäßfarbe</translation>
    </message>
    <message>
        <source>How far the farthest vessels fade into the background</source>
        <translation>Wie stark die entferntesten Gefäße in den Hintergrund übergehen</translation>
    </message>
    <message>
        <source>Only the depth fog cue uses this</source>
        <translation>Nur der Tiefennebel verwendet diesen Wert</translation>
    </message>
    <message>
        <source>k in (1 - |n·v|)^k: higher values keep the colour nearer the silhouette</source>
        <translation>k in (1 - |n·v|)^k: höhere Werte halten die Farbe näher an der Silhouette</translation>
    </message>
    <message>
        <source>Only the Fresnel edge cue uses this</source>
        <translation>Nur der Fresnel-Kantenhinweis verwendet diesen Wert</translation>
    </message>
    <message>
        <source>Material colour of the vessels when no array colours them</source>
        <translation>Materialfarbe der Gefäße, wenn kein Datenfeld sie einfärbt</translation>
    </message>
    <message>
        <source>An array colours the vessels; choose the array None to use a material colour</source>
        <translation>Ein Datenfeld färbt die Gefäße ein; für eine Materialfarbe das Datenfeld „Keines“ wählen</translation>
    </message>
    <message>
        <source>Move the camera to this view of the data</source>
        <translation>Die Kamera auf diese Ansicht der Daten stellen</translation>
    </message>
    <message>
        <source>No data loaded</source>
        <translation>Keine Daten geladen</translation>
    </message>
    <message>
        <source>culled</source>
        <translation>entfallen</translation>
    </message>
    <message>
        <source>cached</source>
        <translation>zwischengespeichert</translation>
    </message>
    <message>
        <source>no frame yet</source>
        <translation>noch kein Bild</translation>
    </message>
    <message>
        <source>total (CPU) %1 ms</source>
        <translation>gesamt (CPU) %1 ms</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Light:</source>
        <translation>Licht:</translation>
    </message>
    <message>
        <source>Where the light comes from, around the view: 0° = from the eye, positive = from the right</source>
        <translation>Woher das Licht kommt, um die Ansicht herum: 0° = vom Auge, positiv = von rechts</translation>
    </message>
    <message>
        <source>Where the light comes from, above or below: positive = from above</source>
        <translation>Woher das Licht kommt, oben oder unten: positiv = von oben</translation>
    </message>
    <message>
        <source>The default light: a little above and left of the eye</source>
        <translation>Das Standardlicht: etwas über und links vom Auge</translation>
    </message>
    <message>
        <source>Left lateral</source>
        <translation>Links lateral</translation>
    </message>
    <message>
        <source>Right lateral</source>
        <translation>Rechts lateral</translation>
    </message>
    <message>
        <source>From -y, +z up (the anterior view of data in patient LPS coordinates)</source>
        <translation>Von -y, +z oben (die anteriore Ansicht von Daten in LPS-Patientenkoordinaten)</translation>
    </message>
    <message>
        <source>From +y, +z up (the posterior view of data in patient LPS coordinates)</source>
        <translation>Von +y, +z oben (die posteriore Ansicht von Daten in LPS-Patientenkoordinaten)</translation>
    </message>
    <message>
        <source>From +x, +z up (the left lateral view of data in patient LPS coordinates)</source>
        <translation>Von +x, +z oben (die Ansicht links lateral von Daten in LPS-Patientenkoordinaten)</translation>
    </message>
    <message>
        <source>From -x, +z up (the right lateral view of data in patient LPS coordinates)</source>
        <translation>Von -x, +z oben (die Ansicht rechts lateral von Daten in LPS-Patientenkoordinaten)</translation>
    </message>
    <message>
        <source>From +z, -y up (the superior view of data in patient LPS coordinates)</source>
        <translation>Von +z, -y oben (die superiore Ansicht von Daten in LPS-Patientenkoordinaten)</translation>
    </message>
    <message>
        <source>From -z, -y up (the inferior view of data in patient LPS coordinates)</source>
        <translation>Von -z, -y oben (die inferiore Ansicht von Daten in LPS-Patientenkoordinaten)</translation>
    </message>
    <message>
        <source>From the front, head up: the patient&apos;s left on the right, as on the coronal slice (the view a DICOM scene opens in)</source>
        <translation>Von vorn, Kopf oben: die linke Seite des Patienten rechts, wie im koronalen Schnitt (die Ansicht, in der eine DICOM-Szene öffnet)</translation>
    </message>
    <message>
        <source>From behind, head up: the patient&apos;s left on the left</source>
        <translation>Von hinten, Kopf oben: die linke Seite des Patienten links</translation>
    </message>
    <message>
        <source>From the patient&apos;s left, head up: anterior on the left</source>
        <translation>Von der linken Seite des Patienten, Kopf oben: anterior links</translation>
    </message>
    <message>
        <source>From the patient&apos;s right, head up: anterior on the right</source>
        <translation>Von der rechten Seite des Patienten, Kopf oben: anterior rechts</translation>
    </message>
    <message>
        <source>From the head towards the feet, anterior up: the patient&apos;s left on the left</source>
        <translation>Vom Kopf zu den Füßen, anterior oben: die linke Seite des Patienten links</translation>
    </message>
    <message>
        <source>From the feet towards the head, anterior up: the patient&apos;s left on the right, as on the axial slice</source>
        <translation>Von den Füßen zum Kopf, anterior oben: die linke Seite des Patienten rechts, wie im axialen Schnitt</translation>
    </message>
</context>
<context>
    <name>vv::gui::panels::EngineNames</name>
    <message>
        <source>Viridis</source>
        <translation>Viridis</translation>
    </message>
    <message>
        <source>Cividis</source>
        <translation>Cividis</translation>
    </message>
    <message>
        <source>Inferno</source>
        <translation>Inferno</translation>
    </message>
    <message>
        <source>Blue-white-red (diverging)</source>
        <translation>Blau-Weiß-Rot (divergierend)</translation>
    </message>
    <message>
        <source>Chromadepth</source>
        <translation>Chromadepth</translation>
    </message>
    <message>
        <source>Pseudo-chromadepth</source>
        <translation>Pseudo-Chromadepth</translation>
    </message>
    <message>
        <source>Dark means deep</source>
        <translation>Dunkel bedeutet tief</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Kein</translation>
    </message>
    <message>
        <source>Vessel chromadepth</source>
        <translation>Gefäß-Chromadepth</translation>
    </message>
    <message>
        <source>Vessel pseudo-chromadepth</source>
        <translation>Gefäß-Pseudo-Chromadepth</translation>
    </message>
    <message>
        <source>Depth fog</source>
        <translation>Tiefennebel</translation>
    </message>
    <message>
        <source>Fresnel-edge pseudo-chromadepth</source>
        <translation>Pseudo-Chromadepth mit Fresnel-Kante</translation>
    </message>
</context>
<context>
    <name>vv::gui::panels::FunctionalPanel</name>
    <message>
        <source>None</source>
        <translation>Keines</translation>
    </message>
    <message>
        <source>Continuous</source>
        <translation>Stufenlos</translation>
    </message>
    <message>
        <source> bins</source>
        <translation> Stufen</translation>
    </message>
    <message>
        <source>Auto (full range)</source>
        <translation>Automatisch (ganzer Bereich)</translation>
    </message>
    <message>
        <source>Percentile 2–98</source>
        <translation>Perzentil 2–98</translation>
    </message>
    <message>
        <source>Manual</source>
        <translation>Manuell</translation>
    </message>
    <message>
        <source>Range:</source>
        <translation>Bereich:</translation>
    </message>
    <message>
        <source>Min / max:</source>
        <translation>Min. / max.:</translation>
    </message>
    <message>
        <source>No data loaded</source>
        <translation>Keine Daten geladen</translation>
    </message>
    <message>
        <source>The loaded meshes have no point arrays</source>
        <translation>Die geladenen Netze haben keine Punktdatenfelder</translation>
    </message>
    <message>
        <source>Choose an array to colour the vessels with</source>
        <translation>Ein Datenfeld zum Einfärben der Gefäße wählen</translation>
    </message>
    <message>
        <source>Point array shown on the vessel wall through the colour map</source>
        <translation>Punktdatenfeld, das über die Farbtabelle auf der Gefäßwand dargestellt wird</translation>
    </message>
    <message>
        <source>Colour map of the array&apos;s values</source>
        <translation>Farbtabelle für die Werte des Datenfelds</translation>
    </message>
    <message>
        <source>Continuous colours, or the range cut into N equal bins</source>
        <translation>Stufenlose Farben oder der Bereich in N gleich große Stufen geteilt</translation>
    </message>
    <message>
        <source>Values mapped to the first and last colour: the full range, the 2nd to 98th percentile, or typed in</source>
        <translation>Werte, die auf die erste und letzte Farbe abgebildet werden: der ganze Bereich, das 2. bis 98. Perzentil oder eingegeben</translation>
    </message>
    <message>
        <source>Values at the first / last colour of the map</source>
        <translation>Werte an der ersten / letzten Farbe der Tabelle</translation>
    </message>
    <message>
        <source>Choose the Manual range to type values</source>
        <translation>Den Bereich „Manuell“ wählen, um Werte einzugeben</translation>
    </message>
    <message>
        <source>Distribution of the array; the lines mark the range (drag them to change it)</source>
        <translation>Verteilung des Datenfelds; die Linien markieren den Bereich (zum Ändern ziehen)</translation>
    </message>
    <message>
        <source>No-data colour</source>
        <translation>Farbe ohne Daten</translation>
    </message>
    <message>
        <source>Colour of vertices without a value (NaN). By default each map has one that never occurs in the map itself</source>
        <translation>Farbe der Punkte ohne Wert (NaN). Standardmäßig hat jede Farbtabelle eine eigene, die in der Tabelle selbst nicht vorkommt</translation>
    </message>
    <message>
        <source>Title of the parameter legend (default: the array&apos;s name and unit)</source>
        <translation>Titel der Parameterlegende (Standard: Name und Einheit des Datenfelds)</translation>
    </message>
    <message>
        <source>The array is shown as labels, each in its own colour</source>
        <translation>Das Datenfeld wird als Labels gezeigt, jedes in einer eigenen Farbe</translation>
    </message>
</context>
<context>
    <name>vv::gui::panels::HistogramWidget</name>
    <message>
        <source>No values</source>
        <translation>Keine Werte</translation>
    </message>
</context>
<context>
    <name>vv::gui::panels::SegmentationPanel</name>
    <message>
        <source>Surface mesh</source>
        <translation>Oberflächennetz</translation>
    </message>
    <message>
        <source>Ray-cast iso-surface</source>
        <translation>Ray-Casting-Isofläche</translation>
    </message>
    <message>
        <source>Surface mesh: the segmented vessels. Ray-cast iso-surface: the volume itself, without segmentation, cut at the iso value</source>
        <translation>Oberflächennetz: die segmentierten Gefäße. Ray-Casting-Isofläche: das Volumen selbst, ohne Segmentierung, beim Isowert geschnitten</translation>
    </message>
    <message>
        <source>Show volume as:</source>
        <translation>Volumen zeigen als:</translation>
    </message>
    <message>
        <source>Iso value:</source>
        <translation>Isowert:</translation>
    </message>
    <message>
        <source>Voxels at or above this value may be vessels</source>
        <translation>Voxel ab diesem Wert können Gefäße sein</translation>
    </message>
    <message>
        <source>Voxels at or below this value may be vessels</source>
        <translation>Voxel bis zu diesem Wert können Gefäße sein</translation>
    </message>
    <message>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <source>Threshold:</source>
        <translation>Schwellenwert:</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Standard</translation>
    </message>
    <message>
        <source>Largest components</source>
        <translation>Größte Komponenten</translation>
    </message>
    <message>
        <source>Component under seed</source>
        <translation>Komponente unter dem Saatpunkt</translation>
    </message>
    <message>
        <source>Keep:</source>
        <translation>Behalten:</translation>
    </message>
    <message>
        <source>Components:</source>
        <translation>Komponenten:</translation>
    </message>
    <message>
        <source>Seed:</source>
        <translation>Saatpunkt:</translation>
    </message>
    <message>
        <source>Remove bone-like components</source>
        <translation>Knochenartige Komponenten entfernen</translation>
    </message>
    <message>
        <source>Drop bright components mostly made of voxels of 1000 HU or more (CT); a vessel touching bone is dropped with it</source>
        <translation>Helle Komponenten entfernen, die überwiegend aus Voxeln ab 1000 HU bestehen (CT); ein Gefäß, das Knochen berührt, wird mit entfernt</translation>
    </message>
    <message>
        <source>All</source>
        <translation>Alle</translation>
    </message>
    <message>
        <source>Decimate the surface to about this many triangles (All: none)</source>
        <translation>Die Oberfläche auf etwa so viele Dreiecke reduzieren (Alle: keine Reduktion)</translation>
    </message>
    <message>
        <source>Surface triangles:</source>
        <translation>Dreiecke der Oberfläche:</translation>
    </message>
    <message>
        <source>Pick Seed</source>
        <translation>Saatpunkt wählen</translation>
    </message>
    <message>
        <source>Click a vessel in the 3-D view: keep only the component under that point</source>
        <translation>Ein Gefäß in der 3-D-Ansicht anklicken: nur die Komponente unter diesem Punkt behalten</translation>
    </message>
    <message>
        <source>Live preview</source>
        <translation>Live-Vorschau</translation>
    </message>
    <message>
        <source>Show a quick segmentation of a downsampled copy whenever a control changes</source>
        <translation>Bei jeder Änderung eine schnelle Segmentierung einer verkleinerten Kopie zeigen</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <source>Segment the whole volume at full resolution</source>
        <translation>Das ganze Volumen in voller Auflösung segmentieren</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Volume: %1 × %2 × %3 voxels%4</source>
        <translation>Volumen: %1 × %2 × %3 Voxel%4</translation>
    </message>
    <message>
        <source>Default: computing…</source>
        <translation>Standard: wird berechnet…</translation>
    </message>
    <message>
        <source>No volume</source>
        <translation>Kein Volumen</translation>
    </message>
    <message>
        <source>(%1, %2, %3): %4</source>
        <translation>(%1, %2, %3): %4</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keiner</translation>
    </message>
    <message>
        <source>Only for scenes segmented from a CT or MR series: open one with File &gt; Open Folder…</source>
        <translation>Nur für Szenen, die aus einer CT- oder MR-Serie segmentiert wurden: eine mit Datei &gt; Ordner öffnen… laden</translation>
    </message>
    <message>
        <source>Default: %1 to %2</source>
        <translation>Standard: %1 bis %2</translation>
    </message>
    <message>
        <source>Default: none (the volume holds a single value)</source>
        <translation>Standard: keiner (das Volumen enthält nur einen Wert)</translation>
    </message>
    <message>
        <source>Wait for Apply to finish, or cancel it</source>
        <translation>Warten, bis Anwenden fertig ist, oder es abbrechen</translation>
    </message>
    <message>
        <source>The segmentation shapes the surface mesh: show the volume as a surface mesh to change it</source>
        <translation>Die Segmentierung formt das Oberflächennetz: zum Ändern das Volumen als Oberflächennetz zeigen</translation>
    </message>
    <message>
        <source>The iso-surface that rays stop at; follows the lower threshold until edited</source>
        <translation>Die Isofläche, an der die Strahlen anhalten; folgt dem unteren Schwellenwert, bis sie geändert wird</translation>
    </message>
    <message>
        <source>Only for the ray-cast iso-surface display</source>
        <translation>Nur für die Anzeige als Ray-Casting-Isofläche</translation>
    </message>
    <message>
        <source>Keep this many of the largest components</source>
        <translation>So viele der größten Komponenten behalten</translation>
    </message>
    <message>
        <source>The seed mode keeps the one component under the seed</source>
        <translation>Der Saatpunkt-Modus behält die eine Komponente unter dem Saatpunkt</translation>
    </message>
    <message>
        <source>Use the default range of the volume&apos;s modality</source>
        <translation>Den Standardbereich der Modalität des Volumens verwenden</translation>
    </message>
    <message>
        <source>The default range is not known yet</source>
        <translation>Der Standardbereich ist noch nicht bekannt</translation>
    </message>
    <message>
        <source>Show the volume as a surface mesh to apply a segmentation</source>
        <translation>Zum Anwenden einer Segmentierung das Volumen als Oberflächennetz zeigen</translation>
    </message>
    <message>
        <source>Pick a seed first</source>
        <translation>Zuerst einen Saatpunkt wählen</translation>
    </message>
    <message>
        <source>Apply is running</source>
        <translation>Anwenden läuft</translation>
    </message>
    <message>
        <source>Stop Apply; the scene stays as it is</source>
        <translation>Anwenden abbrechen; die Szene bleibt, wie sie ist</translation>
    </message>
    <message>
        <source>Nothing to cancel</source>
        <translation>Nichts abzubrechen</translation>
    </message>
    <message>
        <source>Pick a seed: turn on Pick Seed and click a vessel</source>
        <translation>Einen Saatpunkt wählen: „Saatpunkt wählen“ einschalten und ein Gefäß anklicken</translation>
    </message>
    <message>
        <source>No preview: %1</source>
        <translation>Keine Vorschau: %1</translation>
    </message>
    <message>
        <source>full resolution</source>
        <translation>volle Auflösung</translation>
    </message>
    <message>
        <source>one voxel in %1 per axis</source>
        <translation>ein Voxel von %1 je Achse</translation>
    </message>
    <message>
        <source>Preview (%1): %2 triangles; components kept: %3</source>
        <translation>Vorschau (%1): %2 Dreiecke; behaltene Komponenten: %3</translation>
    </message>
    <message>
        <source>Apply failed: %1</source>
        <translation>Anwenden fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Apply cancelled; the scene is unchanged</source>
        <translation>Anwenden abgebrochen; die Szene ist unverändert</translation>
    </message>
    <message>
        <source>Segmenting at full resolution…</source>
        <translation>Segmentierung in voller Auflösung…</translation>
    </message>
    <message>
        <source>Segmented: %1 triangles; components kept: %2 of %3</source>
        <translation>Segmentiert: %1 Dreiecke; behaltene Komponenten: %2 von %3</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Wird abgebrochen…</translation>
    </message>
    <message>
        <source>Ray-cast iso-surface at %1</source>
        <translation>Ray-Casting-Isofläche bei %1</translation>
    </message>
    <message>
        <source>The point lies outside the volume: no seed there</source>
        <translation>Der Punkt liegt außerhalb des Volumens: dort ist kein Saatpunkt möglich</translation>
    </message>
    <message>
        <source>Voxel (%1, %2, %3) holds %4, outside the threshold range %5 to %6: no component there. Click on a vessel, or widen the range.</source>
        <translation>Voxel (%1, %2, %3) hat %4, außerhalb des Schwellenbereichs %5 bis %6: dort gibt es keine Komponente. Ein Gefäß anklicken oder den Bereich erweitern.</translation>
    </message>
    <message>
        <source>Seed at voxel %1</source>
        <translation>Saatpunkt bei Voxel %1</translation>
    </message>
    <message>
        <source>No surface under the mouse: click on a vessel</source>
        <translation>Keine Oberfläche unter der Maus: ein Gefäß anklicken</translation>
    </message>
    <message>
        <source>The volume cannot be ray cast here: %1</source>
        <translation>Das Volumen kann hier nicht per Raycasting dargestellt werden: %1</translation>
    </message>
    <message>
        <source>Correct the signal fall-off (MR)</source>
        <translation>Signalabfall korrigieren (MR)</translation>
    </message>
    <message>
        <source>Divide out the slow fall-off of the MR signal away from the receive coils before thresholding, so that a vessel is not cut off where the signal fades. The thresholds then apply to the corrected values.</source>
        <translation>Den langsamen Abfall des MR-Signals fern der Empfangsspulen vor der Schwellenwertbildung herausrechnen, damit ein Gefäß nicht dort abbricht, wo das Signal schwächer wird. Die Schwellenwerte gelten dann für die korrigierten Werte.</translation>
    </message>
    <message>
        <source>CT values (HU) have no receive-coil fall-off to correct</source>
        <translation>CT-Werte (HU) haben keinen Abfall durch Empfangsspulen, der zu korrigieren wäre</translation>
    </message>
    <message>
        <source>Turn on “Correct the signal fall-off (MR)” or lower the threshold.</source>
        <translation>Schalten Sie „Signalabfall korrigieren (MR)“ ein oder senken Sie den Schwellenwert.</translation>
    </message>
    <message>
        <source>Lower the threshold, or pick a seed in the missing part.</source>
        <translation>Senken Sie den Schwellenwert oder wählen Sie einen Saatpunkt im fehlenden Teil.</translation>
    </message>
    <message>
        <source>Apply it to export, report or send it at full resolution</source>
        <translation>Anwenden, um sie in voller Auflösung zu exportieren, in einen Bericht zu übernehmen oder zu senden</translation>
    </message>
</context>
<context>
    <name>vv::gui::panels::VssPanel</name>
    <message>
        <source>A depth-coded surface in the space between the vessels</source>
        <translation>Eine tiefenkodierte Fläche im Raum zwischen den Gefäßen</translation>
    </message>
    <message>
        <source>Fast (with tolerance)</source>
        <translation>Schnell (mit Toleranz)</translation>
    </message>
    <message>
        <source>Exact</source>
        <translation>Exakt</translation>
    </message>
    <message>
        <source>Paper&apos;s step</source>
        <translation>Schrittweite der Publikation</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <source>Turn the Void Space Surface on to change this</source>
        <translation>Zum Ändern die Void Space Surface einschalten</translation>
    </message>
    <message>
        <source>Interpolation power p: higher values follow the nearest vessel more closely</source>
        <translation>Interpolationsexponent p: höhere Werte folgen dem nächstgelegenen Gefäß enger</translation>
    </message>
    <message>
        <source>How the surface is interpolated: speed against accuracy</source>
        <translation>Wie die Fläche interpoliert wird: Geschwindigkeit gegen Genauigkeit</translation>
    </message>
    <message>
        <source>Largest error of the fast solver, in 1/255 of the depth range</source>
        <translation>Größter Fehler des schnellen Lösers, in 1/255 des Tiefenbereichs</translation>
    </message>
    <message>
        <source>Only the fast solver has a tolerance</source>
        <translation>Nur der schnelle Löser hat eine Toleranz</translation>
    </message>
    <message>
        <source>The paper&apos;s approximation: every k-th contour pixel</source>
        <translation>Die Näherung der Publikation: jedes k-te Konturpixel</translation>
    </message>
    <message>
        <source>Only the paper&apos;s step solver uses k</source>
        <translation>Nur der Schrittweiten-Löser der Publikation verwendet k</translation>
    </message>
    <message>
        <source>Colours of depth on the surface</source>
        <translation>Farben der Tiefe auf der Fläche</translation>
    </message>
    <message>
        <source>Lines of equal depth on the surface</source>
        <translation>Linien gleicher Tiefe auf der Fläche</translation>
    </message>
    <message>
        <source>How dark the iso-lines are</source>
        <translation>Wie dunkel die Isolinien sind</translation>
    </message>
    <message>
        <source>No iso-lines are drawn (set a count first)</source>
        <translation>Es werden keine Isolinien gezeichnet (zuerst eine Anzahl einstellen)</translation>
    </message>
    <message>
        <source>0: flat colours, 100: fully lit surface</source>
        <translation>0: flache Farben, 100: voll beleuchtete Fläche</translation>
    </message>
    <message>
        <source>Shade the surface next to the vessels, so they look anchored on it</source>
        <translation>Die Fläche neben den Gefäßen abschatten, sodass diese auf ihr verankert wirken</translation>
    </message>
    <message>
        <source>Reach of the ambient occlusion, scene units</source>
        <translation>Reichweite der Umgebungsverdeckung, in Szeneneinheiten</translation>
    </message>
    <message>
        <source>Ambient occlusion is off</source>
        <translation>Die Umgebungsverdeckung ist ausgeschaltet</translation>
    </message>
    <message>
        <source>no error bound (step solver)</source>
        <translation>keine Fehlerschranke (Schrittweiten-Löser)</translation>
    </message>
    <message>
        <source>exact</source>
        <translation>exakt</translation>
    </message>
    <message>
        <source>error ≤ %1 / 255</source>
        <translation>Fehler ≤ %1 / 255</translation>
    </message>
    <message>
        <source>Void Space Surface off</source>
        <translation>Void Space Surface aus</translation>
    </message>
    <message>
        <source>solving…</source>
        <translation>wird berechnet…</translation>
    </message>
    <message>
        <source>preview, %1 ms</source>
        <translation>Vorschau, %1 ms</translation>
    </message>
    <message>
        <source>solved in %1 ms</source>
        <translation>berechnet in %1 ms</translation>
    </message>
    <message>
        <source>not solved yet</source>
        <translation>noch nicht berechnet</translation>
    </message>
    <message>
        <source>Solve: %1; %2</source>
        <translation>Berechnung: %1; %2</translation>
    </message>
    <message>
        <source>Visible vessels</source>
        <translation>Sichtbare Gefäße</translation>
    </message>
    <message>
        <source>Fixed</source>
        <translation>Fest</translation>
    </message>
    <message>
        <source>Near / far:</source>
        <translation>Nah / fern:</translation>
    </message>
    <message>
        <source>Visible: the scale spans the vessels in view; fixed: colours keep their depth when the view changes</source>
        <translation>Sichtbar: die Skala umfasst die Gefäße im Bild; fest: die Farben behalten ihre Tiefe, wenn sich die Ansicht ändert</translation>
    </message>
    <message>
        <source>Depths mapped to the near and far end of the scale (viewing distance)</source>
        <translation>Tiefen am nahen und fernen Ende der Skala (Abstand vom Betrachter)</translation>
    </message>
    <message>
        <source>Choose a fixed depth range first</source>
        <translation>Zuerst einen festen Tiefenbereich wählen</translation>
    </message>
    <message>
        <source>Interpolation power p (logarithmic, %L1 to %L2)</source>
        <translation>Interpolationsexponent p (logarithmisch, %L1 bis %L2)</translation>
    </message>
    <message>
        <source>Advanced</source>
        <translation>Erweitert</translation>
    </message>
    <message>
        <source>How the surface is computed: solver, tolerance, solve time</source>
        <translation>Wie die Fläche berechnet wird: Löser, Toleranz, Rechenzeit</translation>
    </message>
</context>
<context>
    <name>vv::render::Legend</name>
    <message>
        <source>… %1 more</source>
        <translation>… %1 weitere</translation>
    </message>
    <message>
        <source>Label %1</source>
        <translation>Label %1</translation>
    </message>
    <message>
        <source>%1 labels, colours repeat</source>
        <translation>%1 Labels, Farben wiederholt</translation>
    </message>
    <message>
        <source>hover names a label</source>
        <translation>Mauszeiger nennt das Label</translation>
    </message>
    <message>
        <source>Depth behind the frontmost vessel</source>
        <translation>Tiefe hinter dem vordersten Gefäß</translation>
    </message>
    <message>
        <source>Viewing distance</source>
        <translation>Abstand vom Betrachter</translation>
    </message>
    <message>
        <source>Centreline: inscribed diameter</source>
        <translation>Mittellinie: einbeschriebener Durchmesser</translation>
    </message>
</context>
<context>
    <name>vv::render::ViewAnnotations</name>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>at the focal plane</source>
        <translation>in der Fokusebene</translation>
    </message>
</context>
<context>
    <name>vv::report::ReportText</name>
    <message>
        <source>as saved in the session</source>
        <translation>wie in der Sitzung gespeichert</translation>
    </message>
    <message>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <source>Coverage</source>
        <translation>Abdeckung</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Min</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>Mittelwert</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>Area &lt; %1</source>
        <translation>Fläche &lt; %1</translation>
    </message>
    <message>
        <source>Area &gt; %1</source>
        <translation>Fläche &gt; %1</translation>
    </message>
    <message>
        <source>Values in the array&apos;s unit.</source>
        <translation>Werte in der Einheit des Datenfelds.</translation>
    </message>
    <message>
        <source>Values in %1.</source>
        <translation>Werte in %1.</translation>
    </message>
    <message>
        <source>Coverage: share of the surface with finite values; the statistics are over that part. Mean and area shares are weighted by surface area, with values interpolated linearly within each triangle.</source>
        <translation>Abdeckung: Anteil der Oberfläche mit endlichen Werten; die Statistik bezieht sich auf diesen Teil. Mittelwert und Flächenanteile sind nach Oberfläche gewichtet, die Werte innerhalb jedes Dreiecks linear interpoliert.</translation>
    </message>
    <message>
        <source>(unnamed)</source>
        <translation>(ohne Namen)</translation>
    </message>
    <message>
        <source>No object has finite values of this parameter.</source>
        <translation>Kein Objekt hat endliche Werte dieses Parameters.</translation>
    </message>
    <message>
        <source>reference</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <source>brute force</source>
        <translation>vollständig (Brute Force)</translation>
    </message>
    <message>
        <source>step</source>
        <translation>Schrittweise</translation>
    </message>
    <message>
        <source>fast</source>
        <translation>schnell</translation>
    </message>
    <message>
        <source>, every %1th contour pixel</source>
        <translation>, jedes %1. Konturpixel</translation>
    </message>
    <message>
        <source> (no error bound)</source>
        <translation> (ohne Fehlerschranke)</translation>
    </message>
    <message>
        <source> (exact)</source>
        <translation> (exakt)</translation>
    </message>
    <message>
        <source> (max. error %1 of normalised depth)</source>
        <translation> (max. Fehler %1 der normierten Tiefe)</translation>
    </message>
    <message>
        <source>female</source>
        <translation>weiblich</translation>
    </message>
    <message>
        <source>male</source>
        <translation>männlich</translation>
    </message>
    <message>
        <source>other</source>
        <translation>divers</translation>
    </message>
    <message>
        <source>Patient name</source>
        <translation>Patientenname</translation>
    </message>
    <message>
        <source>Patient ID</source>
        <translation>Patienten-ID</translation>
    </message>
    <message>
        <source>Birth date</source>
        <translation>Geburtsdatum</translation>
    </message>
    <message>
        <source>Sex</source>
        <translation>Geschlecht</translation>
    </message>
    <message>
        <source>Study date</source>
        <translation>Untersuchungsdatum</translation>
    </message>
    <message>
        <source>Accession number</source>
        <translation>Auftragsnummer</translation>
    </message>
    <message>
        <source>Referring physician</source>
        <translation>Überweisender Arzt</translation>
    </message>
    <message>
        <source>Synthetic demo data generated by VesselView: not patient data.</source>
        <translation>Synthetische Demodaten, von VesselView erzeugt: keine Patientendaten.</translation>
    </message>
    <message>
        <source>Source files</source>
        <translation>Quelldateien</translation>
    </message>
    <message>
        <source>%1 (names withheld: anonymised report)</source>
        <translation>%1 (Namen zurückgehalten: anonymisierter Bericht)</translation>
    </message>
    <message>
        <source>Provenance</source>
        <translation>Herkunft</translation>
    </message>
    <message>
        <source>Void Space Surface</source>
        <translation>Void Space Surface</translation>
    </message>
    <message>
        <source>Depth colour scale</source>
        <translation>Tiefen-Farbskala</translation>
    </message>
    <message>
        <source>Interpolation power p</source>
        <translation>Exponent p</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <source>Iso-lines</source>
        <translation>Isolinien</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Vessel depth cue</source>
        <translation>Tiefenhinweis auf Gefäßen</translation>
    </message>
    <message>
        <source>Ambient occlusion</source>
        <translation>Umgebungsverdeckung</translation>
    </message>
    <message>
        <source>Anti-aliasing (FXAA)</source>
        <translation>Kantenglättung (FXAA)</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>Colour map %1 in %2 bins over %3 – %4.</source>
        <translation>Farbtabelle %1 in %2 Stufen über %3 – %4.</translation>
    </message>
    <message>
        <source>Colour map %1 over %2 – %3.</source>
        <translation>Farbtabelle %1 über %2 – %3.</translation>
    </message>
    <message>
        <source>Values outside are shown in the end colours.</source>
        <translation>Werte außerhalb erscheinen in den Endfarben.</translation>
    </message>
    <message>
        <source>Created %1</source>
        <translation>Erstellt %1</translation>
    </message>
    <message>
        <source>%1, ID %2</source>
        <translation>%1, ID %2</translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation>Seite %1 von %2</translation>
    </message>
    <message>
        <source>Patient and study</source>
        <translation>Patient und Untersuchung</translation>
    </message>
    <message>
        <source>Findings</source>
        <translation>Befund</translation>
    </message>
    <message>
        <source>No findings entered.</source>
        <translation>Kein Befund eingegeben.</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>Second view</source>
        <translation>Zweite Ansicht</translation>
    </message>
    <message>
        <source>Parameter statistics — %1</source>
        <translation>Parameterstatistik — %1</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>Daten</translation>
    </message>
    <message>
        <source>Rendering settings</source>
        <translation>Darstellungseinstellungen</translation>
    </message>
    <message>
        <source>Far view</source>
        <translation>Fernansicht</translation>
    </message>
    <message>
        <source>Medium view</source>
        <translation>Mittlere Ansicht</translation>
    </message>
    <message>
        <source>Close view</source>
        <translation>Nahansicht</translation>
    </message>
    <message>
        <source>Anterior view</source>
        <translation>Ansicht von anterior</translation>
    </message>
    <message>
        <source>Posterior view</source>
        <translation>Ansicht von posterior</translation>
    </message>
    <message>
        <source>Left view</source>
        <translation>Ansicht von links</translation>
    </message>
    <message>
        <source>Right view</source>
        <translation>Ansicht von rechts</translation>
    </message>
    <message>
        <source>Superior view</source>
        <translation>Ansicht von superior</translation>
    </message>
    <message>
        <source>Inferior view</source>
        <translation>Ansicht von inferior</translation>
    </message>
    <message>
        <source>Reading the patient and study</source>
        <translation>Patient und Untersuchung werden gelesen</translation>
    </message>
    <message>
        <source>Rendering the image</source>
        <translation>Bild wird gerendert</translation>
    </message>
    <message>
        <source>Rendering the report&apos;s view</source>
        <translation>Ansicht des Berichts wird gerendert</translation>
    </message>
    <message>
        <source>Rendering the second view</source>
        <translation>Zweite Ansicht wird gerendert</translation>
    </message>
    <message>
        <source>Laying out the PDF</source>
        <translation>PDF wird gesetzt</translation>
    </message>
    <message>
        <source>default (fitted)</source>
        <translation>Standard (eingepasst)</translation>
    </message>
    <message>
        <source>Writing the files</source>
        <translation>Dateien werden geschrieben</translation>
    </message>
    <message>
        <source>yyyy-MM-dd</source>
        <extracomment>Date format of the report (QDate::toString); e.g. dd.MM.yyyy in German.</extracomment>
        <translation>dd.MM.yyyy</translation>
    </message>
    <message>
        <source>yyyy-MM-dd HH:mm</source>
        <extracomment>Date and time format of the report (QDateTime::toString).</extracomment>
        <translation>dd.MM.yyyy HH:mm</translation>
    </message>
    <message>
        <source>Vessel tree report</source>
        <translation>Gefäßbaum-Bericht</translation>
    </message>
    <message>
        <source>Not for diagnostic use.</source>
        <translation>Nicht für diagnostische Zwecke.</translation>
    </message>
    <message>
        <source>Default view, the whole tree fitted</source>
        <translation>Standardansicht, der ganze Baum eingepasst</translation>
    </message>
    <message>
        <source>%1 view</source>
        <translation>Ansicht %1</translation>
    </message>
    <message>
        <source>anonymised</source>
        <translation>anonymisiert</translation>
    </message>
    <message>
        <source>Slice with segmentation</source>
        <translation>Schicht mit Segmentierung</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>DICOM series</source>
        <translation>DICOM-Serie</translation>
    </message>
    <message>
        <source>Reading the exported report</source>
        <translation>Exportierter Bericht wird gelesen</translation>
    </message>
    <message>
        <source>Left lateral view</source>
        <translation>Ansicht links lateral</translation>
    </message>
    <message>
        <source>Right lateral view</source>
        <translation>Ansicht rechts lateral</translation>
    </message>
    <message>
        <source>Segmentation</source>
        <translation>Segmentierung</translation>
    </message>
    <message>
        <source>Accuracy</source>
        <translation>Treffsicherheit</translation>
    </message>
    <message>
        <source>Response time</source>
        <translation>Antwortzeit</translation>
    </message>
    <message>
        <source>Accuracy (mean, 95 % CI)</source>
        <translation>Treffsicherheit
(Mittelwert, 95-%-KI)</translation>
    </message>
    <message>
        <source>chance level</source>
        <translation>Zufallsniveau</translation>
    </message>
    <message>
        <source>Response time (ms)</source>
        <translation>Antwortzeit (ms)</translation>
    </message>
    <message>
        <source>Condition</source>
        <translation>Bedingung</translation>
    </message>
    <message>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <source>95 % CI</source>
        <translation>95-%-KI</translation>
    </message>
    <message>
        <source>Median</source>
        <translation>Median</translation>
    </message>
    <message>
        <source>Median CI</source>
        <translation>KI des Medians</translation>
    </message>
    <message>
        <source>Rank sum</source>
        <translation>Rangsumme</translation>
    </message>
    <message>
        <source>Per participant and condition: %1. Mean with its Student&apos;s t interval; median with the interval between two order statistics (it covers %2).</source>
        <translation>Je Teilnehmer und Bedingung: %1. Mittelwert mit seinem t-Intervall nach Student; Median mit dem Intervall zwischen zwei Ordnungsstatistiken (es überdeckt %2).</translation>
    </message>
    <message>
        <source>the share of correct answers</source>
        <translation>der Anteil richtiger Antworten</translation>
    </message>
    <message>
        <source>the median response time</source>
        <translation>der Median der Antwortzeit</translation>
    </message>
    <message>
        <source>Pair</source>
        <translation>Paar</translation>
    </message>
    <message>
        <source>Rank-sum difference</source>
        <translation>Differenz der Rangsummen</translation>
    </message>
    <message>
        <source>Corrected p</source>
        <translation>Korrigiertes p</translation>
    </message>
    <message>
        <source>Significant</source>
        <translation>Signifikant</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>Bonferroni</source>
        <translation>Bonferroni</translation>
    </message>
    <message>
        <source>Holm</source>
        <translation>Holm</translation>
    </message>
    <message>
        <source>Post-hoc comparisons of the conditions&apos; rank sums (Siegel and Castellan), corrected by %1 at α = %2; the critical difference of rank sums (Bonferroni) is %3.</source>
        <translation>Post-hoc-Vergleiche der Rangsummen der Bedingungen (Siegel und Castellan), korrigiert nach %1 bei α = %2; die kritische Differenz der Rangsummen (Bonferroni) beträgt %3.</translation>
    </message>
    <message>
        <source>Friedman&apos;s test: χ²(%1) = %2, p %3; Kendall&apos;s W = %4.</source>
        <translation>Friedman-Test: χ²(%1) = %2, p %3; Kendalls W = %4.</translation>
    </message>
    <message>
        <source>Participant</source>
        <translation>Teilnehmer</translation>
    </message>
    <message>
        <source>Answers</source>
        <translation>Antworten</translation>
    </message>
    <message>
        <source>Correct</source>
        <translation>Richtig</translation>
    </message>
    <message>
        <source>Median time</source>
        <translation>Median der Zeit</translation>
    </message>
    <message>
        <source>p (chance)</source>
        <translation>p (Zufall)</translation>
    </message>
    <message>
        <source>Included</source>
        <translation>Einbezogen</translation>
    </message>
    <message>
        <source>%1: no answer in %2 condition(s), first %3</source>
        <translation>%1: keine Antwort in %2 Bedingung(en), zuerst %3</translation>
    </message>
    <message>
        <source>%1: at chance level, %2 of %3 correct (p = %4)</source>
        <translation>%1: auf Zufallsniveau, %2 von %3 richtig (p = %4)</translation>
    </message>
    <message>
        <source>Participants</source>
        <translation>Teilnehmer</translation>
    </message>
    <message>
        <source>Conditions</source>
        <translation>Bedingungen</translation>
    </message>
    <message>
        <source>Results files</source>
        <translation>Ergebnisdateien</translation>
    </message>
    <message>
        <source>A participant is excluded when their main-block answers are not above chance (the one-sided exact binomial test against %1 gives p ≥ %2), or when they have no answer in some condition.</source>
        <translation>Ausgeschlossen wird, wessen Antworten im Hauptblock nicht über dem Zufallsniveau liegen (der einseitige exakte Binomialtest gegen %1 ergibt p ≥ %2) oder wer in einer Bedingung keine Antwort gegeben hat.</translation>
    </message>
    <message>
        <source>Excluded — %1</source>
        <translation>Ausgeschlossen — %1</translation>
    </message>
    <message numerus="yes">
        <source>%n answer(s) repeated a stimulus already answered (a resumed run): only the first counts.</source>
        <translation>
            <numerusform>%n Antwort wiederholte einen schon beantworteten Stimulus (ein fortgesetzter Durchlauf): nur die erste zählt.</numerusform>
            <numerusform>%n Antworten wiederholten einen schon beantworteten Stimulus (ein fortgesetzter Durchlauf): nur die erste zählt.</numerusform>
        </translation>
    </message>
    <message>
        <source>Participants&apos; answers (main block)</source>
        <translation>Antworten der Teilnehmer (Hauptblock)</translation>
    </message>
    <message>
        <source>Depth-judgement study</source>
        <translation>Studie zur Tiefenwahrnehmung</translation>
    </message>
    <message>
        <source>Pairs that differ significantly: %1</source>
        <translation>Signifikant verschiedene Paare: %1</translation>
    </message>
    <message>
        <source>No pair of conditions differs significantly.</source>
        <translation>Kein Paar von Bedingungen unterscheidet sich signifikant.</translation>
    </message>
    <message>
        <source>Coarse facets</source>
        <translation>Grobe Facetten</translation>
    </message>
    <message>
        <source>smoothed up close (the wall moved by at most %1)</source>
        <translation>aus der Nähe geglättet (die Wand um höchstens %1 verschoben)</translation>
    </message>
    <message>
        <source>Blank (—): %1.</source>
        <translation>Leer (—): %1.</translation>
    </message>
    <message>
        <source>Nothing measured.</source>
        <translation>Nichts gemessen.</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>Messungen</translation>
    </message>
    <message>
        <source>Drawn %1 times as high as long, to be read.</source>
        <translation>%1-fach überhöht gezeichnet, damit sie lesbar ist.</translation>
    </message>
</context>
</TS>
