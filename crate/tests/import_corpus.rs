//! The import corpus: whole vlab objects (cpfg's `.l` with its view file, function files and
//! colour map or materials) and L-Py models as their authors wrote them, beyond the files of
//! `tests/import/` (sources and licences in `tests/import-corpus/SOURCES.md`). Each must import,
//! resolve without errors, carry exactly its expected notes (so that no import claims a complete
//! translation when something was dropped or approximated) and build a plant of the recorded size.
//!
//! The sizes are those of a reference run of this translation (two checked against the source:
//! SOURCES.md says which); neither cpfg nor L-Py runs on this machine, so the others
//! guard the translation against regressions rather than prove it equal to the source tool's.
//! Native only: it reads the corpus from disk, and proptest is not a wasm32 dependency.
#![cfg(not(target_arch = "wasm32"))]

mod shared;

use meristem::import::{self, Dialect, Import, ObjectFile};
use meristem::pipeline::{build, BuildOptions};
use shared::object;
use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/import-corpus")
}

/// Every entry: its path under the corpus, the modules and segments of its plant, and its notes
/// (line, a piece of the message), exactly.
type Entry = (&'static str, usize, usize, &'static [(usize, &'static str)]);

/// A file that does not yet build the plant its source implies: why, then what it gives now (an
/// [`Entry`]; 0 and 0 when the translation does not build at all), so that any change is seen.
type Failure = (&'static str, Entry);

/// The share of the corpus that must build its plant (issue 21: 95 %).
const GOAL: f64 = 0.95;

/// The share reached so far (79 of 82 files, 96.3 %): it may only rise.
const FLOOR: f64 = 0.96;

const CORPUS: &[Entry] = &[
    (
        "vlab/01-Lychnis",
        1370,
        5235,
        &[
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
            (
                29,
                "cpfg's _ is not a Meristem command; kept as a module the turtle ignores",
            ),
            (76, "cpfg's @! is not a Meristem command; dropped"),
            (76, "cpfg's @# is not a Meristem command; dropped"),
            (
                81,
                "cpfg's f before a control point of a generalized cylinder moves along th",
            ),
            (
                81,
                "cpfg's @Gc marks a control point of a generalized cylinder; Meristem's s",
            ),
        ],
    ),
    ("vlab/01-hormone-up", 27, 11, &[]),
    ("vlab/01-pipe-model", 137, 30, &[]),
    ("vlab/01-planation", 198, 65, &[]),
    ("vlab/01-quadratic-Koch", 7608, 4096, &[]),
    ("vlab/02-decussate", 937, 341, &[]),
    ("vlab/02-hormone-down", 27, 11, &[]),
    ("vlab/02-snowflake-exercise", 82, 0, &[]),
    (
        "vlab/03-decussate-shaded",
        233,
        85,
        &[(
            0,
            "the materials of material.mat become their diffuse colours: their ambien",
        )],
    ),
    ("vlab/03-signal-down", 27, 11, &[]),
    ("vlab/04-compound", 452, 130, &[]),
    ("vlab/04-florigen", 19, 16, &[]),
    (
        "vlab/04-perspective",
        234,
        85,
        &[(
            0,
            "the materials of material.mat become their diffuse colours: their ambien",
        )],
    ),
    ("vlab/05-florigen-param", 19, 16, &[]),
    (
        "vlab/05-monopodial",
        354,
        117,
        &[(
            0,
            "the materials of material.mat become their diffuse colours: their ambien",
        )],
    ),
    (
        "vlab/06-comp-leaf-perspective",
        135,
        11,
        &[
            (
                0,
                "the view file's surface l is read from leaf.s, which was not opened with",
            ),
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
            (
                22,
                "cpfg's @Tx is not a Meristem command; kept as a module the turtle ignore",
            ),
            (22, "cpfg's @ is not a Meristem command; dropped"),
        ],
    ),
    ("vlab/06-compound-param", 402, 161, &[]),
    ("vlab/06-florigen+auxin", 19, 16, &[]),
    ("vlab/07-acrotonic-2-signals", 150, 72, &[]),
    ("vlab/07-fractal-ferns", 6032, 1983, &[]),
    (
        "vlab/07-leaf-rnd",
        95,
        11,
        &[
            (
                0,
                "cpfg draws its random numbers with another generator than Meristem's",
            ),
            (
                0,
                "the view file's surface l is read from leaf.s, which was not opened with",
            ),
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
        ],
    ),
    ("vlab/08-basipetal-2-signals", 130, 52, &[]),
    ("vlab/08-continuous-time", 852, 341, &[]),
    (
        "vlab/08-leaf-pos",
        140,
        16,
        &[
            (
                0,
                "cpfg draws its random numbers with another generator than Meristem's",
            ),
            (
                0,
                "the view file's surface l is read from leaf.s, which was not opened with",
            ),
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
        ],
    ),
    ("vlab/09-continuous-decomp", 852, 341, &[]),
    (
        "vlab/09-monopodial-spiral",
        224,
        44,
        &[
            (
                0,
                "the view file's surface l is read from leaf.s, which was not opened with",
            ),
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
        ],
    ),
    (
        "vlab/09-mycelis-schematic",
        148,
        23,
        &[
            (
                12,
                "cpfg's '#' without a value widens by the width increment; Meristem has n",
            ),
            (
                12,
                "cpfg's @oZG is not a Meristem command; kept as a module the turtle ignor",
            ),
            (
                15,
                "cpfg's @o(d) draws a disc of diameter d facing the viewer",
            ),
        ],
    ),
    (
        "vlab/10-sympodial",
        5114,
        1022,
        &[(
            0,
            "the materials of material.mat become their diffuse colours: their ambien",
        )],
    ),
    (
        "vlab/11-acropetal-1-signal",
        379,
        48,
        &[
            (
                30,
                "cpfg's '#' without a value widens by the width increment; Meristem has n",
            ),
            (
                40,
                "cpfg's @o(d) draws a disc of diameter d facing the viewer",
            ),
        ],
    ),
    ("vlab/11-alternating-exercise", 852, 341, &[]),
    (
        "vlab/11-sympodial-asym",
        4684,
        936,
        &[
            (
                0,
                "the view file's surface l is read from leaf.s, which was not opened with",
            ),
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
        ],
    ),
    (
        "vlab/12-basipetal-1-signal",
        381,
        48,
        &[
            (
                30,
                "cpfg's '#' without a value widens by the width increment; Meristem has n",
            ),
            (
                40,
                "cpfg's @o(d) draws a disc of diameter d facing the viewer",
            ),
        ],
    ),
    ("vlab/DragonCurve", 1277, 256, &[]),
    (
        "vlab/HilbertPanels",
        214,
        385,
        &[
            (
                27,
                "cpfg's predecessor Sl is 2 modules (S l); Meristem's predecessor is one ",
            ),
            (
                28,
                "cpfg's predecessor Sr is 2 modules (S r); Meristem's predecessor is one ",
            ),
            (
                30,
                "cpfg's predecessor Tl is 2 modules (T l); Meristem's predecessor is one ",
            ),
            (
                31,
                "cpfg's predecessor Tr is 2 modules (T r); Meristem's predecessor is one ",
            ),
        ],
    ),
    (
        "vlab/RandomMoss",
        2445,
        699,
        &[(
            0,
            "cpfg draws its random numbers with another generator than Meristem's",
        )],
    ),
    (
        "vlab/Ring",
        32,
        32,
        &[(
            5,
            "'ring lsystem' is not part of the notation Meristem imports; skipped",
        )],
    ),
    (
        "vlab/Shedding",
        2244,
        1149,
        &[
            (
                29,
                "a production for cpfg's ',' becomes one for Meristem's ';', which also s",
            ),
            (
                33,
                "cpfg's @o(d) draws a disc of diameter d facing the viewer",
            ),
        ],
    ),
    ("lpy/01-equilat-triangle.lpy", 6, 3, &[]),
    ("lpy/03-koch-curve.lpy", 2390, 1024, &[]),
    ("lpy/04-sierpinski.lpy", 728, 0, &[]),
    (
        "lpy/05-simple-sympodial-plant.lpy",
        694,
        126,
        &[
            (15, "L-Py's @o is not a Meristem command"),
            (
                20,
                "the Python function '__initialiseContext__' is not translated",
            ),
        ],
    ),
    ("lpy/07-continuous-growth.lpy", 8, 7, &[]),
    (
        "lpy/09-flower-continous-growth.lpy",
        6042,
        453,
        &[
            (17, "the Python function 'Start' is not translated"),
            (21, "the Python function 'End' is not translated"),
            (25, "the Python function 'StartEach' is not translated"),
            (28, "the Python function 'EndEach' is not translated"),
            (
                71,
                "a production for L-Py's '_' becomes one for Meristem's '!', which also s",
            ),
        ],
    ),
    (
        "lpy/12-hidden-markov-1stem.lpy",
        598,
        149,
        &[
            (
                0,
                "L-Py draws its random numbers with another generator than Meristem's",
            ),
            (27, "the Python function 'Start' is not translated"),
            (
                50,
                "the Python code 'r = random()' is not translated (Meristem imports bodie",
            ),
            (
                56,
                "the Python code 'r = random()' is not translated (Meristem imports bodie",
            ),
            (
                85,
                "the Python function '__initialiseContext__' is not translated",
            ),
        ],
    ),
    ("lpy/13-branched-signal.lpy", 16, 7, &[]),
    ("lpy/Frame.lpy", 1, 3, &[]),
    ("lpy/branching.lpy", 6, 3, &[]),
    ("lpy/combined.lpy", 37, 7, &[]),
    ("lpy/ex_lsystem3.lpy", 134, 48, &[]),
    ("lpy/filledPolygons.lpy", 16, 3, &[]),
    ("lpy/generalizedCylinders.lpy", 12, 6, &[]),
    ("lpy/harderExample.lpy", 61, 10, &[]),
    ("lpy/movement.lpy", 2, 3, &[]),
    (
        "lpy/orientation.lpy",
        2,
        3,
        &[(
            2,
            "'Pinpoint' is not a module Meristem knows; kept as a module its turtle i",
        )],
    ),
    ("lpy/polygons.lpy", 7, 6, &[]),
    (
        "lpy/resolution.lpy",
        5,
        3,
        &[(
            2,
            "'SectionResolution' is not a module Meristem knows; kept as a module its",
        )],
    ),
    ("lpy/scale.lpy", 13, 7, &[]),
    ("lpy/visualize.lpy", 10, 7, &[]),
    ("lpy/width.lpy", 7, 4, &[]),
    (
        "lpy/10-random-tree.lpy",
        11072,
        1472,
        &[
            (
                0,
                "L-Py draws its random numbers with another generator than Meristem's: th",
            ),
            (10, "the Python function 'Start' is not translated"),
            (
                14,
                "L-Py's @GsG is not a Meristem command; kept as a module the turtle ignor",
            ),
        ],
    ),
    (
        "lpy/11a-markov-1stem.lpy",
        221,
        139,
        &[
            (
                0,
                "L-Py draws its random numbers with another generator than Meristem's",
            ),
            (13, "the Python function 'Start' is not translated"),
        ],
    ),
    (
        "vlab/03-Borcher-Honda",
        182,
        45,
        &[
            (66, "cpfg's @c without a diameter is as wide as the line"),
            (
                66,
                "cpfg's @L draws a text label; Meristem draws no text, so the label is dr",
            ),
        ],
    ),
    (
        "lpy/17-open-lsystem-simple-growth.lpy",
        861,
        313,
        &[(
            6,
            "L-Py's turtle grows along +Z and turns towards Y, Meristem's grows along",
        )],
    ),
    (
        "lpy/ex_lsystem2.lpy",
        861,
        313,
        &[(
            6,
            "L-Py's turtle grows along +Z and turns towards Y, Meristem's grows along",
        )],
    ),
    (
        "vlab/02-Borchert-Slade",
        14296,
        673,
        &[
            (
                0,
                "cpfg draws its random numbers with another generator than Meristem's: th",
            ),
            (
                41,
                "cpfg's predecessor L(age);(c,b)!(r,a,d,f) is 3 modules; Meristem's prede",
            ),
        ],
    ),
    (
        "vlab/topiary",
        34,
        10,
        &[
            (
                37,
                "cpfg's predecessor F(n) A is 2 modules; Meristem's predecessor is one mo",
            ),
            (
                53,
                "cpfg's @c(d) draws a disc of diameter d in the turtle's H–L plane",
            ),
        ],
    ),
    (
        "vlab/01-herb-lily",
        5,
        50,
        &[
            (
                0,
                "the materials of plant.mat become their diffuse colours: their ambient, ",
            ),
            (12, "cpfg's @# is not a Meristem command; dropped"),
            (
                17,
                "cpfg's f before a control point of a generalized cylinder moves along th",
            ),
            (
                17,
                "cpfg's @Gc marks a control point of a generalized cylinder; Meristem's s",
            ),
        ],
    ),
    (
        "vlab/LilyLeaf",
        5,
        50,
        &[
            (
                0,
                "the materials of plant.mat become their diffuse colours: their ambient, ",
            ),
            (12, "cpfg's @# is not a Meristem command; dropped"),
            (
                17,
                "cpfg's f before a control point of a generalized cylinder moves along th",
            ),
            (
                17,
                "cpfg's @Gc marks a control point of a generalized cylinder; Meristem's s",
            ),
        ],
    ),
    (
        "lpy/13a-flow1stem-random.lpy",
        12,
        30,
        &[
            (
                0,
                "L-Py draws its random numbers with another generator than Meristem's: th",
            ),
            (
                12,
                "the Python function 'txt' returns str(round(val,2))[:5]: '[' in an expre",
            ),
            (15, "the Python function 'Start' is not translated"),
            (
                44,
                "the Python code 'global sumauxin' changes the global sumauxin, which not",
            ),
            (
                46,
                "the Python code 'sumauxin += auxin' changes the global sumauxin, which n",
            ),
            (
                54,
                "L-Py's @L draws a text label; Meristem draws no text, so the label is dr",
            ),
            (
                63,
                "the Python function '__initialiseContext__' is not translated",
            ),
        ],
    ),
    (
        "lpy/13b-flow1stem-diffusecontinuouslyfromroot.lpy",
        11,
        30,
        &[
            (
                8,
                "the Python function 'txt' returns str(round(val,2))[:5]: '[' in an expre",
            ),
            (
                44,
                "L-Py's @L draws a text label; Meristem draws no text, so the label is dr",
            ),
            (
                49,
                "the Python function '__initialiseContext__' is not translated",
            ),
        ],
    ),
    (
        "lpy/13c-flow1stem-diffusecontfromapexwithdeg.lpy",
        21,
        60,
        &[
            (
                11,
                "the Python function 'txt' returns str(round(val,2))[:5]: '[' in an expre",
            ),
            (
                48,
                "L-Py's @L draws a text label; Meristem draws no text, so the label is dr",
            ),
            (
                54,
                "the Python function '__initialiseContext__' is not translated",
            ),
        ],
    ),
    (
        "vlab/03-pallaea",
        5,
        2171,
        &[
            (
                0,
                "the materials of plant.mat become their diffuse colours: their ambient, ",
            ),
            (
                0,
                "cpfg draws its random numbers with another generator than Meristem's: th",
            ),
            (
                34,
                "the statement 'srand(1)' restarts cpfg's random generator when the produ",
            ),
            (75, "cpfg's @# is not a Meristem command; dropped"),
            (
                75,
                "cpfg's @Gt is not a Meristem command; kept as a module the turtle ignore",
            ),
            (
                75,
                "cpfg's @Gr is not a Meristem command; kept as a module the turtle ignore",
            ),
            (
                79,
                "cpfg's f before a control point of a generalized cylinder moves along th",
            ),
            (
                79,
                "cpfg's @Gc marks a control point of a generalized cylinder; Meristem's s",
            ),
        ],
    ),
    (
        "vlab/04-paintbrush",
        3,
        1859,
        &[
            (
                0,
                "the materials of plant.mat become their diffuse colours: their ambient, ",
            ),
            (
                0,
                "cpfg draws its random numbers with another generator than Meristem's: th",
            ),
            (
                25,
                "the statement 'srand(1)' restarts cpfg's random generator when the produ",
            ),
            (
                27,
                "the statement 'roll - roll/L0' assigns nothing (it has no effect in cpfg",
            ),
            (43, "cpfg's @# is not a Meristem command; dropped"),
            (
                43,
                "cpfg's @Gt is not a Meristem command; kept as a module the turtle ignore",
            ),
            (
                43,
                "cpfg's @Gr is not a Meristem command; kept as a module the turtle ignore",
            ),
            (
                51,
                "cpfg's f before a control point of a generalized cylinder moves along th",
            ),
            (
                51,
                "cpfg's @Gc marks a control point of a generalized cylinder; Meristem's s",
            ),
        ],
    ),
    (
        "vlab/ShootRoot",
        11,
        4,
        &[
            (
                47,
                "the statement 'go=1' changes cpfg's global variable go during the deriva",
            ),
            (
                47,
                "the statement 'shoot = cs' changes cpfg's global variable shoot during t",
            ),
            (
                47,
                "the statement 'root=cr' changes cpfg's global variable root during the d",
            ),
            (
                47,
                "cpfg's printf prints to the console; it is not translated (the plant is ",
            ),
            (
                59,
                "the statement 'go=0' changes cpfg's global variable go during the deriva",
            ),
            (
                64,
                "cpfg's predecessor XI(b,m,v,c,s,w) is 2 modules; Meristem's predecessor ",
            ),
            (
                98,
                "cpfg's printf prints to the console; it is not translated (the plant is ",
            ),
            (
                106,
                "cpfg's printf prints to the console; it is not translated (the plant is ",
            ),
            (145, "cpfg's @c without a diameter is as wide as the line"),
            (
                147,
                "cpfg's @L draws a text label; Meristem draws no text, so the label is dr",
            ),
        ],
    ),
    (
        "vlab/Lilac",
        4333,
        2160,
        &[
            (
                0,
                "the materials of materials.mat become their diffuse colours: their ambie",
            ),
            (
                72,
                "cpfg's predecessor AXIOM is 5 modules (A X I O M); Meristem's predecesso",
            ),
            (
                100,
                "cpfg's _ is not a Meristem command; kept as a module the turtle ignores",
            ),
        ],
    ),
    (
        "vlab/MonopodialSpiral",
        223,
        44,
        &[
            (
                0,
                "the view file's stropism line (0.0 1.0 0, 0.05) is not translated: the p",
            ),
            (
                0,
                "the materials of material.mat become their diffuse colours: their ambien",
            ),
        ],
    ),
    (
        "vlab/12-two-trees",
        61,
        2,
        &[
            (
                0,
                "the materials of tree.mat become their diffuse colours: their ambient, e",
            ),
            (
                49,
                "cpfg's printf prints to the console; it is not translated (the plant is ",
            ),
            (
                49,
                "cpfg's StartEach: statement 'if(d==0){DEL=DEL+1;d=DEL+1;printf(\"Year %.0",
            ),
            (
                53,
                "cpfg's EndEach: statement 'if(d==1){stop(1);}' is not translated: Merist",
            ),
            (
                55,
                "cpfg's ?E(…) asks the environment program (a light or space model run be",
            ),
            (
                56,
                "cpfg's f before a control point of a generalized cylinder moves along th",
            ),
            (
                62,
                "Meristem rejects the translation `L(f,age,del,vig) : (n >= WHENMOVE)&&(a",
            ),
            (
                93,
                "Meristem rejects the translation `-(a) > [!(w1,n1,f1)L : (n < WHENMOVE)&",
            ),
            (
                100,
                "Meristem rejects the translation `-(a) > !(w1,n1,f1)L : (n < WHENMOVE)&&",
            ),
            (
                125,
                "Meristem rejects the translation `!(w0,n0,f0) > L(fl,age,del,vig)[!(w1,n",
            ),
            (
                128,
                "a production for cpfg's '#' becomes one for Meristem's '!', which also s",
            ),
            (
                133,
                "a production for cpfg's ',' becomes one for Meristem's ';', which also s",
            ),
            (
                153,
                "the statement 'srand(SEED)' restarts cpfg's random generator when the pr",
            ),
            (
                153,
                "cpfg's @Tx is not a Meristem command; kept as a module the turtle ignore",
            ),
            (
                160,
                "cpfg's @G is not a Meristem command; kept as a module the turtle ignores",
            ),
            (
                166,
                "cpfg's @Gc marks a control point of a generalized cylinder; Meristem's s",
            ),
            (
                171,
                "cpfg's predecessor F(vig,n)#(w) is 2 modules; Meristem's predecessor is ",
            ),
            (
                171,
                "a production for cpfg's '#' becomes one for Meristem's '!', which also s",
            ),
            (
                172,
                "cpfg's predecessor F(vig,n)#(w) is 2 modules; Meristem's predecessor is ",
            ),
            (
                172,
                "a production for cpfg's '#' becomes one for Meristem's '!', which also s",
            ),
            (
                176,
                "cpfg's predecessor F(vig,n)#(w) is 2 modules; Meristem's predecessor is ",
            ),
            (
                176,
                "a production for cpfg's '#' becomes one for Meristem's '!', which also s",
            ),
            (
                270,
                "cpfg's @Tf is not a Meristem command; kept as a module the turtle ignore",
            ),
            (
                270,
                "~m names a surface the object's view file does not give (or whose file w",
            ),
            (
                270,
                "Meristem rejects the translation `L(del,vig) : (n > WHENMOVE+NUMSTEPS+1)",
            ),
            (
                277,
                "Meristem rejects the translation `L(del,vig) : (n > WHENMOVE+NUMSTEPS+1)",
            ),
            (
                284,
                "Meristem rejects the translation `L(del,vig) : n > WHENMOVE+NUMSTEPS+1 -",
            ),
        ],
    ),
    (
        "vlab/22-insect-realistic",
        30,
        6,
        &[
            (
                19,
                "cpfg's StartEach: statement 's=0' changes the variable s during the deri",
            ),
            (
                19,
                "cpfg's printf prints to the console; it is not translated (the plant is ",
            ),
            (
                20,
                "cpfg's EndEach: statement 's=1' changes the variable s during the deriva",
            ),
            (
                24,
                "cpfg's _ is not a Meristem command; kept as a module the turtle ignores",
            ),
            (
                29,
                "cpfg's predecessor f(l,t)/(n)h is 3 modules; Meristem's predecessor is o",
            ),
            (
                42,
                "cpfg's predecessor aF is 2 modules (a F); Meristem's predecessor is one ",
            ),
            (
                43,
                "the statement 'c=c+SINC' changes cpfg's global variable c during the der",
            ),
            (
                47,
                "cpfg's predecessor bF is 2 modules (b F); Meristem's predecessor is one ",
            ),
            (
                49,
                "Meristem rejects the translation `* < 4 > F]g -> 5`: ']' has no matching",
            ),
            (
                73,
                "cpfg's predecessor A(n,m)B is 2 modules; Meristem's predecessor is one m",
            ),
            (
                89,
                "~b names a surface the object's view file does not give (or whose file w",
            ),
        ],
    ),
    (
        "lpy/11b-markov-nstems.lpy",
        3125,
        1651,
        &[
            (
                0,
                "L-Py draws its random numbers with another generator than Meristem's: th",
            ),
            (13, "the Python function 'Start' is not translated"),
            (
                23,
                "the Python code 'm = 1' sets the global m, which productions read; Meris",
            ),
            (
                44,
                "L-Py's @c is not a Meristem command; kept as a module the turtle ignores",
            ),
        ],
    ),
];

/// The files that do not yet build the plant their source implies, each with the reason.
const FAILURES: &[Failure] = &[
("modules carry Python objects (T(SegmentData())) and the bending is computed with PlantGL vectors in Python; nothing of it is expressible, not even the axiom", ("lpy/16a-branch-bending.lpy", 0, 0, &[(
0, "nothing to derive: no axiom could be imported"),(
2, "Python imports are not translated"),(
3, "Python imports are not translated"),(
14, "the Python statement 'Forward,Backward,Growth=range(3)' is not translate"),(
20, "the Python statement 'class SegmentData:' is not translated"),(
42, "the Python function 'setMode' is not translated"),(
51, "the Python function 'isFORWARD' is not translated"),(
54, "the Python function 'isBACKWARD' is not translated"),(
57, "the Python function 'isGROWTH' is not translated"),(
61, "the Python function 'Start' is not translated"),(
66, "the Python function 'StartEach' is not translated"),(
73, "the Python function 'EndEach' is not translated"),(
86, "Meristem rejects the translation `axiom: T(SegmentData())B(N)`: unknown "),(
93, "the Python code 'a.cummass = a.mass + b.cummass' is not translated (Meri"),(
101, "the Python code 'a.cummass = a.mass + b.cummass' is not translated (Meri"),(
109, "the Python code 'a.cummass = a.mass' is not translated (Meristem imports"),(
115, "the Python code 'global error' is not translated (Meristem imports bodie"),(
127, "the Python code 'global error' is not translated (Meristem imports bodie"),(
139, "the Python code 'print (\"GROWTH ------------------ GROWTH\")' is not tran"),(
147, "Meristem rejects the translation `B(n) : n>0 -> S(SegmentData())B(n-1)`:"),(
153, "Meristem rejects the translation `T(c) -> !(S_DIAM*1.4)F(S_LEN*12)`: 'T'"),(
157, "'a.H' is Python, not a number expression; the production is skipped"),(
161, "'c.H' is Python, not a number expression; the production is skipped"),(
167, "the Python function '__initialiseContext__' is not translated"),])),
("modules carry Python objects (SegmentData()) and the bending is computed with PlantGL vectors in Python; nothing of it is expressible, not even the axiom", ("lpy/16b-branching-system-bending.lpy", 0, 0, &[(
0, "nothing to derive: no axiom could be imported"),(
2, "Python imports are not translated"),(
3, "Python imports are not translated"),(
15, "the Python statement 'Forward,Backward,Growth=range(3)' is not translate"),(
22, "the Python statement 'class SegmentData:' is not translated"),(
46, "the Python function 'setMode' is not translated"),(
55, "the Python function 'isFORWARD' is not translated"),(
58, "the Python function 'isBACKWARD' is not translated"),(
61, "the Python function 'isGROWTH' is not translated"),(
65, "the Python function 'Start' is not translated"),(
68, "the Python function 'StartEach' is not translated"),(
73, "the Python function 'EndEach' is not translated"),(
86, "Meristem rejects the translation `axiom: T(SegmentData())B(N)[+(30)B(N)["),(
93, "the Python code 'a.cummass = a.mass + b.cummass' is not translated (Meri"),(
101, "the Python code 'a.cummass = a.mass + b.cummass + c.cummass' is not tran"),(
111, "the Python code 'a.cummass = a.mass + b.cummass' is not translated (Meri"),(
119, "the Python code 'a.cummass = a.mass' is not translated (Meristem imports"),(
125, "the Python code 'global error' is not translated (Meristem imports bodie"),(
137, "the Python code 'global error' is not translated (Meristem imports bodie"),(
149, "the Python code 'global error' is not translated (Meristem imports bodie"),(
161, "the Python code 'print (\"GROWTH ------------------ GROWTH\")' is not tran"),(
169, "Meristem rejects the translation `B(n) : n>0 -> S(SegmentData())B(n-1)`:"),(
174, "Meristem rejects the translation `T(c) -> !(S_DIAM*1.4)F(S_LEN*12)`: 'T'"),(
178, "'a.H' is Python, not a number expression; the production is skipped"),(
182, "'c.H' is Python, not a number expression; the production is skipped"),(
186, "'c.H' is Python, not a number expression; the production is skipped"),(
192, "the Python function '__initialiseContext__' is not translated"),])),



(
"the spiral's only production computes its primordia in a while loop (translated: an auxiliary module rewritten until its condition fails) along the contour curve (curveX, curveY, curveGAL of profile.con, a file this copy of the object does not hold: the whole object in tests/collections/cpfg/Ridley builds, see cpfg_collection.rs), so it is skipped",
(
        "vlab/Ridley",
        2,
        0,
        &[
            (0, "the materials of material.mat become their diffuse colours: their ambien"),
            (0, "the contour file profile.con could not be read"),
            (5, "cpfg's curveGAL(1, …): the view file gives no contour 1"),
            (14, "cpfg's curveY(1, …): the view file gives no contour 1 that could be read"),
        ],
    )),

];

fn import_entry(path: &str) -> Import {
    let full = root().join(path);
    if full.is_dir() {
        import::import_object(&object(&full))
    } else {
        let text = std::fs::read_to_string(&full).expect("UTF-8 model");
        assert_eq!(import::detect(&text, path), Some(Dialect::Lpy), "{path}");
        import::import(&text, Dialect::Lpy)
    }
}

#[test]
fn the_corpus_holds_every_file_it_lists_and_no_other() {
    let mut listed: Vec<String> = Vec::new();
    for kind in ["vlab", "lpy"] {
        for e in std::fs::read_dir(root().join(kind))
            .expect("corpus")
            .flatten()
        {
            listed.push(format!("{kind}/{}", e.file_name().to_string_lossy()));
        }
    }
    listed.sort();
    let mut expected: Vec<String> = CORPUS
        .iter()
        .chain(FAILURES.iter().map(|f| &f.1))
        .map(|e| e.0.to_string())
        .collect();
    expected.sort();
    assert_eq!(listed, expected);
    assert!(CORPUS.len() >= 40);
}

/// The share of the whole corpus (the files that build their plant and those that do not yet)
/// that builds its plant.
fn share() -> f64 {
    CORPUS.len() as f64 / (CORPUS.len() + FAILURES.len()) as f64
}

#[test]
fn the_share_of_the_whole_corpus_that_builds_its_plant_does_not_fall() {
    assert!(
        share() >= FLOOR,
        "{} of {} files ({:.1} %) build their plant, fewer than before ({:.1} %)",
        CORPUS.len(),
        CORPUS.len() + FAILURES.len(),
        100.0 * share(),
        100.0 * FLOOR
    );
}

#[test]
fn at_least_95_percent_of_the_whole_corpus_builds_its_plant() {
    assert!(
        share() >= GOAL,
        "{} of {} files ({:.1} %) build their plant; the goal is {:.0} %",
        CORPUS.len(),
        CORPUS.len() + FAILURES.len(),
        100.0 * share(),
        100.0 * GOAL
    );
}

#[test]
fn every_failure_still_imports_as_recorded_with_its_reason() {
    let mut wrong = Vec::new();
    for (why, entry) in FAILURES {
        assert!(!why.is_empty(), "{}", entry.0);
        check(entry, &mut wrong);
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// Imports one entry and says in `wrong` where its notes or its plant differ from the record.
fn check(&(path, modules, segments, notes): &Entry, wrong: &mut Vec<String>) {
    let result = import_entry(path);
    let mut unmatched: Vec<&(usize, &str)> = notes.iter().collect();
    for note in &result.notes {
        match unmatched
            .iter()
            .position(|(line, piece)| *line == note.line && note.message.contains(piece))
        {
            Some(i) => {
                unmatched.remove(i);
            }
            None => wrong.push(format!("{path}: unexpected note {note:?}")),
        }
    }
    if !unmatched.is_empty() {
        wrong.push(format!("{path}: missing notes {unmatched:?}"));
    }
    let b = build(&result.text, &BuildOptions::default());
    let size = if b.ok() {
        (b.plant.stats.modules, b.plant.stats.segments)
    } else {
        (0, 0)
    };
    if size != (modules, segments) {
        wrong.push(format!(
            "{path}: {size:?} modules and segments, not {:?} {:?}",
            (modules, segments),
            b.diagnostics
        ));
    }
}

#[test]
fn every_corpus_file_imports_with_exactly_its_notes_and_builds_its_plant() {
    let mut wrong = Vec::new();
    for entry in CORPUS {
        if entry.1 + entry.2 == 0 {
            wrong.push(format!("{}: a corpus entry must build a plant", entry.0));
        }
        check(entry, &mut wrong);
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn an_object_gives_its_view_and_functions_and_the_l_alone_says_what_it_lacks() {
    let dir = root().join("vlab/05-monopodial");
    let whole = import::import_object(&object(&dir));
    assert!(whole.text.contains("#angle 9\n"), "{}", whole.text);
    assert!(whole.text.contains("#table internode 0 0 "));
    assert!(whole.text.contains("internode("));
    let alone = std::fs::read_to_string(dir.join("leaf.l")).expect("leaf.l");
    let alone = import::import(&alone, Dialect::Cpfg);
    let said: Vec<&str> = alone.notes.iter().map(|n| n.message.as_str()).collect();
    assert!(
        said.iter()
            .any(|m| m.contains("func(1, …) reads function 1 of the object's view file")),
        "{said:?}"
    );
    assert!(
        said.iter()
            .any(|m| m.contains("colours are in the object's view file")),
        "{said:?}"
    );
}

/// cpfg draws `line style: cylinder` (and polygons) as wide as the width in the model's units and
/// `initial line width: 4 pixels` in pixels (vlab `cpfg/interpret.c` and `cpfg/irisGL.c`): the
/// first imports with `#width_unit 1` and its mesh's width unit is one model unit; the second
/// keeps Meristem's unit relative to the plant.
#[test]
fn a_view_file_that_draws_cylinders_gives_widths_in_model_units() {
    let unit = meristem::vocabulary::DirectiveKind::WidthUnit.written();
    let build_of = |text: &str| {
        let b = build(text, &BuildOptions::default());
        b.plant
    };
    let cylinders = import::import_object(&object(&root().join("vlab/05-monopodial")));
    assert!(
        cylinders.text.contains(&format!("{unit} 1\n")),
        "{}",
        cylinders.text
    );
    assert_eq!(build_of(&cylinders.text).mesh.width_unit, 1.0);
    let pixels = import::import_object(&object(&root().join("vlab/01-hormone-up")));
    assert!(!pixels.text.contains(&unit), "{}", pixels.text);
    let plant = build_of(&pixels.text);
    assert_ne!(plant.mesh.width_unit, 1.0, "relative to the plant's size");
}

#[test]
fn a_zipped_object_imports_as_its_folder_does() {
    let dir = root().join("vlab/09-monopodial-spiral");
    let files = object(&dir);
    let entries: Vec<(String, &[u8])> = files
        .iter()
        .map(|f| {
            (
                format!("09-monopodial-spiral/{}", f.name),
                f.bytes.as_slice(),
            )
        })
        .collect();
    let entries: Vec<(&str, &[u8])> = entries.iter().map(|(n, b)| (n.as_str(), *b)).collect();
    let zip = meristem::export::zip::stored(&entries).expect("zip");
    let (zipped, dialect) = import::import_files(&[ObjectFile {
        name: "spiral.zip".into(),
        bytes: zip,
    }]);
    assert_eq!(dialect, Some(Dialect::Cpfg));
    assert_eq!(zipped, import::import_object(&files));
    let (broken, dialect) = import::import_files(&[ObjectFile {
        name: "spiral.zip".into(),
        bytes: b"PK\x03\x04 not really".to_vec(),
    }]);
    assert_eq!(dialect, None);
    assert!(broken.text.is_empty());
    assert!(broken.notes[0]
        .message
        .starts_with("spiral.zip: not a zip archive"));
}

/// Any bytes in any file of an object (the archive, the view file, a function file, the colour
/// map, the L-system) give a translation that resolves, or notes: never a panic or a hang.
#[test]
fn any_bytes_in_an_object_give_a_translation_or_a_note() {
    use proptest::prelude::*;
    use proptest::test_runner::{Config, TestRunner};
    let base = object(&root().join("vlab/08-leaf-pos"));
    let mut runner = TestRunner::new(Config {
        cases: 64,
        ..Config::default()
    });
    let strategy = (
        0..base.len() + 1,
        proptest::collection::vec(any::<u8>(), 0..400),
        any::<u16>(),
    );
    runner
        .run(&strategy, |(which, noise, at)| {
            let mut files = base.clone();
            match files.get_mut(which) {
                // Overwrite part of one file with noise.
                Some(f) => {
                    let at = at as usize % (f.bytes.len() + 1);
                    let end = (at + noise.len()).min(f.bytes.len());
                    f.bytes.splice(at..end, noise.iter().copied());
                }
                None => files.push(ObjectFile {
                    name: "noise.zip".into(),
                    bytes: noise,
                }),
            }
            let (result, _) = import::import_files(&files);
            if !result.is_empty() {
                let (file, mut d) = meristem::syntax::parse(&result.text);
                d.extend(meristem::model::resolve(&file).1);
                prop_assert!(!meristem::diagnostics::has_errors(&d), "{}", result.text);
            }
            Ok(())
        })
        .expect("no input breaks the importer");
}
