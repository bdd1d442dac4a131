// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/Cli.h"

#include <algorithm>
#include <ostream>
#include <string>

#include "cli/ReportCommand.h"
#include "common/SettingsSchema.h"
#include "vv/Version.h"
#include "vv/core/Error.h"

namespace vv::cli {

int soakCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

namespace {

constexpr const char* kUsageText =
    "usage: vesselview-cli <command> [options]\n"
    "\n"
    "commands:\n"
    "  info FILE... [--json] [--scale S]   meshes, triangle counts, arrays with ranges and units\n"
    "  demo -o FILE.vtp [--seed N] [--generations G] [--voxel-size MM]\n"
    "                                       write the synthetic demo vessel tree\n"
    "  demo --dicom DIR                     write it voxelised as a CT angiography series\n"
    "  demo --aorta -o FILE.vtp [--triangles N]\n"
    "                                       an aorta with an aneurysm and its iliacs,\n"
    "                                       decimated to N triangles (a coarse segmentation)\n"
    "  render FILE -o IMAGE.png [--size WxH] [--array NAME|none] [--colormap NAME]\n"
    "         [--background #rrggbb] [--vss on|off] [--scale cd|pcd|dmd] [--p P]\n"
    "         [--isolines N] [--solver NAME] [--tolerance T] [--timings]\n"
    "         [--cue none|vessel-cd|vessel-pcd|fog|fresnel] [--legends on|off] [--bins N]\n"
    "         [--values auto|continuous|categories]\n"
    "         [--view far|medium|close|anterior|posterior|left|right|superior|inferior]\n"
    "         [--depth-out DEPTH.pfm] [--ao on|off] [--aa on|off] [--light AZ,EL] [--tile N]\n"
    "         [--orientation-marker on|off] [--scale-bar on|off] [--smooth-coarse on|off]\n"
    "         [--centerlines on|off] [--centerline-colour diameter|branch]\n"
    "         DICOM input (a folder, DICOMDIR, image or SEG file): [--series UID]\n"
    "         [--threshold LO:HI] [--components N] [--seed I,J,K] [--bone-removal on|off]\n"
    "         [--intensity-correction on|off] [--triangles N]\n"
    "                      segments the vessels (CT default 200:700 HU; MR from the\n"
    "                      histogram after dividing out the signal fall-off)\n"
    "         [--raycast [--iso HU]]   ray casts the volume instead (no segmentation)\n"
    "                                       render a mesh file or DICOM vessels offscreen to PNG, "
    "with the\n"
    "                                       void space surface (VSS) on by default;\n"
    "                                       --timings prints per-pass ms as JSON on stdout;\n"
    "                                       colour maps: viridis, cividis, inferno,\n"
    "                                       blue-white-red; --bins N = N discrete bins;\n"
    "                                       --cue = a depth cue on the vessels; legends\n"
    "                                       (depth, parameter) are on by default\n"
    "                                       and so are the orientation marker (patient\n"
    "                                       L/R/A/P/S/I for DICOM, else x/y/z) and the\n"
    "                                       scale bar (mm at the focal plane)\n"
    "                                       --ao: ambient occlusion, --aa: FXAA (both on)\n"
    "                                       --smooth-coarse on (default): a mesh under 150k\n"
    "                                       triangles is drawn Loop-subdivided where its\n"
    "                                       median edge spans 8 px or more (no facet\n"
    "                                       blobs along the lit VSS; the wall moves by\n"
    "                                       at most half an edge, said in a note)\n"
    "                                       --light: the key light's azimuth and elevation\n"
    "                                       in degrees (view space; default the headlight);\n"
    "                                       --tile N: render in tiles of at most N pixels a\n"
    "                                       side (small GPUs; same image)\n"
    "                                       --centerlines on: the surface's centrelines\n"
    "                                       (as `centerline` finds them) drawn through\n"
    "                                       the vessels, by inscribed diameter (with its\n"
    "                                       legend) or one colour and number per branch\n"
    "                                       (needs an X display; use xvfb-run -a);\n"
    "                                       anatomical views in LPS patient coordinates\n"
    "                                       (+x left, +y posterior, +z superior): anterior,\n"
    "                                       posterior, left, right head up, superior and\n"
    "                                       inferior anterior up; DICOM opens in the\n"
    "                                       anterior view (far, medium, close too), meshes\n"
    "                                       looking down -z;\n"
    "                                       --depth-out writes the linear depth (PFM,\n"
    "                                       background +Inf) that `vss --depth` reads\n"
    "  render --session F.vvs -o IMAGE.png [options as for render]\n"
    "                                       what the GUI saved in the session: its files\n"
    "                                       (DICOM: the stored series and segmentation),\n"
    "                                       camera and display settings, as File > Export\n"
    "                                       Image renders them; options after --session\n"
    "                                       override it\n"
    "  segment DICOM -o SURFACE.stl|.vtp|.ply [DICOM options as for render]\n"
    "                                       the segmented vessel surface in patient LPS\n"
    "                                       mm with its label array (.vtp) and the series\n"
    "                                       and settings that made it (VTP field data, STL\n"
    "                                       header, PLY comments); warns when a bright\n"
    "                                       tube continues past the segmentation\n"
    "  centerline FILE -o CENTERLINES.vtp [--source X,Y,Z] [--target X,Y,Z ...] [--step MM]\n"
    "         [--scale F] [--sections SECTIONS.csv] [--surface-out SURFACE.vtp]\n"
    "         [--json [--landmark KEY=X,Y,Z ...]] [--smooth-folded on|off]\n"
    "         [DICOM options as for render]\n"
    "                                       centrelines (VMTK's method), sections with their\n"
    "                                       diameters, stenoses and bifurcation angles of a\n"
    "                                       mesh or of segmented DICOM vessels; landmarks,\n"
    "                                       the lengths between them and the aortic sizing\n"
    "                                       table; exit code 3 when the surface cannot be\n"
    "                                       analysed\n"
    "  report FILE -o REPORT.pdf [render options as for render] [--png IMAGE.png]\n"
    "         [--transparent] [--dicom-sc SC.dcm] [--dicom-pdf DOC.dcm] [--paper a4|letter]\n"
    "         [--measurements MEAS.json [--dicom-sr SR.dcm]]\n"
    "         [--title TEXT] [--note TEXT] [--second-view VIEW] [--below V] [--above V]\n"
    "         [--anonymise] [--lang en|de] [--disclaimer TEXT] [DICOM options as for render]\n"
    "         [--patient-name PN] [--patient-id ID] [--birth-date YYYYMMDD] [--sex F|M|O]\n"
    "         [--study-date YYYYMMDD] [--accession A] [--referring-physician PN]\n"
    "         [--slice axial|coronal|sagittal[@MM]]\n"
    "  report --session F.vvs -o REPORT.pdf [options as for report]\n"
    "  report --batch LIST.txt --out-dir DIR [--formats pdf,png,dicom-sc,dicom-pdf] [...]\n"
    "                                       PDF report (findings, view at 300 dpi, legends,\n"
    "                                       parameter statistics per object with area below /\n"
    "                                       above V, settings), PNG up to 8K, DICOM\n"
    "                                       Secondary Capture / Encapsulated PDF in a new\n"
    "                                       study (DICOM input: the source study and its\n"
    "                                       patient block; meshes: the patient options above);\n"
    "                                       --slice (DICOM series): a page with that slice and\n"
    "                                       its segmentation, as the GUI's slice view, at MM\n"
    "                                       (LPS mm, or as the views write it: I120, A12.5;\n"
    "                                       default the middle slice, or a session's)\n"
    "                                       --measurements: a Measurements section from a\n"
    "                                       centerline --json file (landmarks, lengths, aortic\n"
    "                                       sizing, branches); --dicom-sr: the same as a DICOM\n"
    "                                       TID 1500 Structured Report in the study\n"
    "                                       --lang: the report's language; --batch: one input\n"
    "                                       a line, a summary,\n"
    "                                       exit code of the first failure\n"
    "  study make SCENE... -o DIR [--conditions NAME,...] [--pairs N] [--seed S] [--size WxH]\n"
    "         [--condition NAME:SETTING=VALUE,...] [--training-pairs N]\n"
    "                                       the depth-judgement study's stimuli: marker pairs\n"
    "                                       by the paper's criteria, an image per pair and\n"
    "                                       condition, manifest.json\n"
    "  study analyse RESULTS.csv... [-o STUDY.pdf] [--lang en|de] [--paper a4|letter]\n"
    "         [--tables DIR] [--alpha A] [--correction bonferroni|holm]\n"
    "                                       the depth-judgement study's answers: exclusions,\n"
    "                                       per-condition accuracy and response time with 95 %\n"
    "                                       intervals, Friedman's test, post-hoc comparisons;\n"
    "                                       -o: as a PDF with its charts\n"
    "  vss --depth IN.pfm -o OUT.pfm [--p P] [--solver NAME] [--step K] [--tolerance T]\n"
    "      [--fixed-range A,B] [--labels OUT.png] [--stats]\n"
    "                                       void space surface of a PFM depth image\n"
    "  bench [--mesh FILE] [--size WxH | --sizes WxH,WxH...] [--views far,medium,close]\n"
    "        [--p 2,4,8] [--runs N] [--reference-runs N]\n"
    "        [--solvers reference,brute,step3,step5,fast]\n"
    "        [--tolerances 0.5,2,8] [--out DIR] [--depth-out DIR] [--quick]\n"
    "                                       VSS solvers: error against run time (Markdown\n"
    "                                       table; DIR/vss.csv, vss-table.md,\n"
    "                                       vss-error-vs-time.png; demo tree by default);\n"
    "                                       --sizes: several sizes in one run, with each\n"
    "                                       solver's time relative to the first size\n"
    "                                       (above 1280x720 the brute solver is the\n"
    "                                       ground truth)\n"
    "  artefacts [--aorta] [--mesh FILE]... [--triangles 10000,30000,60000|none]\n"
    "            [--size WxH] [--view far|medium|close] [--p P] [--light AZ,EL]\n"
    "            [--reference-scale 3|5|7|none] [--subdivide LEVELS] [--save DIR]\n"
    "                                       lit VSS: artefact score along silhouettes of the\n"
    "                                       demo tree (--aorta: an aorta with an aneurysm and\n"
    "                                       its iliacs; decimated to 13000 by default), its\n"
    "                                       decimated copies (each also Loop-subdivided with\n"
    "                                       --subdivide) and FILEs, of the same view\n"
    "                                       supersampled (default 3x), and 2-6 px against\n"
    "                                       12-30 px from the vessels (Markdown table);\n"
    "                                       --save writes the meshes it made into DIR\n"
    "  pacs echo --node AE@HOST:PORT [--aet OURS] [--timeout S]\n"
    "            [--tls-ca CA.pem [--tls-cert CERT.pem --tls-key KEY.pem]]\n"
    "  pacs find --node N [--patient-name P] [--patient-id ID] [--date-from YYYYMMDD]\n"
    "            [--date-to YYYYMMDD] [--modality M] [--description D] [--accession A]\n"
    "            [--study UID (series level)]\n"
    "  pacs get --node N --study UID [--series UID] --store DIR [--store-limit BYTES|NGB]\n"
    "           [--move --port P [--bind ADDR] [LIMITS]]\n"
    "  pacs send --node N FILE...\n"
    "  pacs listen --store DIR --port P [--bind ADDR] [--aet OURS] --allow AE@HOST...\n"
    "              [--for SECONDS] [--store-limit BYTES|NGB] [LIMITS]\n"
    "              [--tls-ca CA.pem --tls-cert CERT.pem --tls-key KEY.pem]\n"
    "    LIMITS of our listener: [--max-associations N (16)] [--max-per-address N (8)]\n"
    "              [--max-connections N (64)] [--request-timeout S (5)]\n"
    "              [--max-instance BYTES|NMB|NGB (4GB)] [--max-association SIZE (50GB)]\n"
    "                                       DICOM networking (docs/dicom-networking.md):\n"
    "                                       C-ECHO; C-FIND of studies / series (JSON);\n"
    "                                       C-GET (or C-MOVE to a listener of ours) into\n"
    "                                       the local study store; C-STORE with each\n"
    "                                       instance's status; the storage SCP, which\n"
    "                                       lets in only the --allow nodes, on the\n"
    "                                       interface --bind (IPv4; default all); --tls-ca:\n"
    "                                       DICOM over TLS (the listener, and get --move,\n"
    "                                       with our --tls-cert / --tls-key, letting in\n"
    "                                       only peers whose certificate chains to CA);\n"
    "                                       --store-limit: least recently used studies go\n"
    "                                       (never an open one), also NMB; 1 GB = 10^9 B\n"
    "                                       LIMITS: associations served at once;\n"
    "                                       connections from one allowed host and in all\n"
    "                                       (more are closed at once; other hosts: 2\n"
    "                                       each, 8 together); seconds a connection has\n"
    "                                       to ask for an association; the largest\n"
    "                                       instance and association (more is refused)\n"
    "  --version, --help\n"
    "\n"
    "exit codes: 0 ok, 1 internal error, 2 usage, 3 unreadable or invalid input\n"
    "            (also a session naming a missing file or holding a bad value),\n"
    "            4 cannot write output, 5 the peer refused or failed (pacs: refused\n"
    "            connection or association, timeout, failure status, instance refused)\n";

/// What a setting's option takes ("on|off", "N", "#rrggbb", the names).
std::string metavar(const app::Setting& s) {
    switch (s.type) {
        case app::SettingType::Bool:
            return "on|off";
        case app::SettingType::Int:
            return "N";
        case app::SettingType::Real:
            return "X";
        case app::SettingType::Choice: {
            std::string names = app::choiceNames(s);
            std::replace(names.begin(), names.end(), ',', '|');
            std::erase(names, ' ');
            return names;
        }
        case app::SettingType::Color:
            return "#rrggbb";
        case app::SettingType::Text:
            return "TEXT";
    }
    return {};
}

/// "Label: range unit, default value" of a setting's option.
std::string settingSummary(const app::Setting& s) {
    std::string text = s.label;
    if (s.type == app::SettingType::Int || s.type == app::SettingType::Real) {
        text += ": " + app::validValues(s) + (s.unit.empty() ? "" : " " + std::string(s.unit));
    }
    if (s.type != app::SettingType::Text) {
        text += ", default " + app::settingText(s, app::defaultValue(s));
    }
    return text;
}

/// `--help`: every display setting with an option, from the settings schema.
std::string settingsHelp() {
    constexpr std::size_t kColumn = 39;
    std::string text = "\ndisplay settings of render and report (sessions hold them too):\n";
    for (const app::Setting& s : app::settingsSchema()) {
        if (s.cliOption.empty()) {
            continue;
        }
        std::string line = "  " + std::string(s.cliOption) + " ";
        std::string summary = settingSummary(s);
        if (s.key == "style.light[0]") {  // --light AZ,EL: two settings
            line += "AZ,EL";
        } else if (s.key == "style.light[1]") {
            line.clear();
        } else {
            line += metavar(s);
        }
        line += line.size() + 1 > kColumn ? "\n" + std::string(kColumn, ' ')
                                          : std::string(kColumn - line.size(), ' ');
        text += line + summary + "\n";
    }
    return text;
}

}  // namespace

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    if (args.empty()) {
        err << kUsageText;
        return kUsage;
    }
    const std::string& command = args.front();
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    try {
        if (command == "--help" || command == "-h" || command == "help") {
            out << kUsageText << settingsHelp();
            return kOk;
        }
        if (command == "--version") {
            out << "vesselview-cli " << vv::kVersion << "\n";
            return kOk;
        }
        if (command == "info") {
            return infoCommand(rest, out, err);
        }
        if (command == "demo") {
            return demoCommand(rest, out, err);
        }
        if (command == "render") {
            return renderCommand(rest, out, err);
        }
        if (command == "report") {
            return reportCommand(rest, out, err);
        }
        if (command == "vss") {
            return vssCommand(rest, out, err);
        }
        if (command == "bench") {
            return benchCommand(rest, out, err);
        }
        if (command == "artefacts") {
            return artefactsCommand(rest, out, err);
        }
        if (command == "segment") {
            return segmentCommand(rest, out, err);
        }
        if (command == "centerline") {
            return centerlineCommand(rest, out, err);
        }
        if (command == "study") {
            return studyCommand(rest, out, err);
        }
        if (command == "pacs") {
            return pacsCommand(rest, out, err);
        }
        if (command == "soak") {  // hidden: scripts/soak (SoakCommand.cpp)
            return soakCommand(rest, out, err);
        }
        throw UsageError("unknown command '" + command + "'");
    } catch (const UsageError& e) {
        err << "vesselview-cli: " << e.what() << "\n\n" << kUsageText;
        return kUsage;
    } catch (const OutputError& e) {
        err << "vesselview-cli: " << e.what() << "\n";
        return kCannotWrite;
    } catch (const vv::RenderError& e) {
        // No usable OpenGL: not the input's fault.
        err << "vesselview-cli: cannot render: " << e.what() << "\n";
        return kInternalError;
    } catch (const vv::InvalidArgumentError& e) {
        err << "vesselview-cli: " << e.what() << "\n";
        return kUsage;
    } catch (const vv::Error& e) {
        err << "vesselview-cli: " << e.what() << "\n";
        return kInvalidInput;
    } catch (const std::exception& e) {
        err << "vesselview-cli: internal error: " << e.what() << "\n";
        return kInternalError;
    }
}

}  // namespace vv::cli
