// SPDX-License-Identifier: MIT
// Frame graph: culling, empty passes, ordering, validation, transient lifetimes, imports
// and the Graphviz dump. Passes record their execution in an event list, and so does the
// allocator, so the tests check what actually ran and when textures lived.
#include "engine/render/frame_graph.hpp"

#include "engine/core/error.hpp"
#include "expect_error.hpp"  // tests/support

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using engine::render::ConcreteTexture;
using engine::render::FrameGraph;
using engine::render::FrameGraphTexture;
using engine::render::PassStatus;
using engine::render::ResourceLifetime;
using engine::render::TextureAllocator;
using engine::render::FrameGraphTextureDesc;
using ssam::testing::errorOf;
using testing::AllOf;
using testing::ElementsAre;
using testing::HasSubstr;
using testing::IsEmpty;

using Events = std::vector<std::string>;

constexpr FrameGraphTextureDesc kDesc{.width = 64, .height = 32, .format = 7, .samples = 1};

struct Output {
    FrameGraphTexture texture;
};

// A pass that reads `inputs`, then declares the rest with `declare(builder, out)`; running, it
// records its name in `events`.
template <class Declare>
const Output& recordedPass(FrameGraph& fg, Events& events, const std::string& pass,
                           const std::vector<FrameGraphTexture>& inputs, Declare&& declare) {
    return fg.addPass<Output>(
        pass,
        [&](FrameGraph::Builder& builder, Output& out) {
            for (FrameGraphTexture input : inputs) builder.read(input);
            declare(builder, out);
        },
        [&events, pass](const FrameGraph::Resources&, const Output&) { events.push_back(pass); });
}

// A pass that reads `inputs` and writes a texture `texture` it creates.
FrameGraphTexture produce(FrameGraph& fg, Events& events, const std::string& pass, const std::string& texture,
                          const std::vector<FrameGraphTexture>& inputs = {}) {
    return recordedPass(fg, events, pass, inputs,
                        [&](FrameGraph::Builder& builder, Output& out) {
                            out.texture = builder.write(builder.create(texture, kDesc));
                        })
        .texture;
}

// A pass that reads `inputs` and draws into `target` on top of what is there.
FrameGraphTexture modify(FrameGraph& fg, Events& events, const std::string& pass, FrameGraphTexture target,
                         const std::vector<FrameGraphTexture>& inputs = {}) {
    return recordedPass(
               fg, events, pass, inputs,
               [&](FrameGraph::Builder& builder, Output& out) { out.texture = builder.write(builder.read(target)); })
        .texture;
}

// A side-effect pass (present, capture) that reads `inputs`.
void present(FrameGraph& fg, Events& events, const std::string& pass, const std::vector<FrameGraphTexture>& inputs) {
    recordedPass(fg, events, pass, inputs, [](FrameGraph::Builder& builder, Output&) { builder.sideEffect(); });
}

// Hands out textures 100, 101, ... and records "alloc <name>" / "release <name>".
TextureAllocator recordingAllocator(Events& events) {
    auto next = std::make_shared<ConcreteTexture>(100);
    auto names = std::make_shared<std::map<ConcreteTexture, std::string>>();
    return {
        .allocate =
            [&events, next, names](std::string_view name, const FrameGraphTextureDesc& desc) {
                EXPECT_EQ(desc, kDesc);
                const ConcreteTexture texture = (*next)++;
                (*names)[texture] = std::string(name);
                events.push_back("alloc " + std::string(name));
                return texture;
            },
        .release =
            [&events, names](ConcreteTexture texture, const FrameGraphTextureDesc&) {
                events.push_back("release " + names->at(texture));
                names->erase(texture);
            },
    };
}

// --- culling -------------------------------------------------------------------------

TEST(FrameGraphCulling, PassWhoseOutputNobodyReadsIsCulled) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture color = produce(fg, events, "opaque", "color");
    produce(fg, events, "unused", "junk");
    present(fg, events, "present", {color});

    fg.execute(recordingAllocator(events));

    EXPECT_EQ(fg.passStatus("unused"), PassStatus::Culled);
    EXPECT_EQ(fg.passStatus("opaque"), PassStatus::Executes);
    EXPECT_THAT(fg.executedPassNames(), ElementsAre("opaque", "present"));
    EXPECT_THAT(events, ElementsAre("alloc color", "opaque", "present", "release color"));
}

TEST(FrameGraphCulling, UnreadChainIsCulledWhole) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture a = produce(fg, events, "A", "a");
    const FrameGraphTexture b = produce(fg, events, "B", "b", {a});
    produce(fg, events, "C", "c", {b});

    fg.execute(recordingAllocator(events));

    EXPECT_EQ(fg.passStatus("A"), PassStatus::Culled);
    EXPECT_EQ(fg.passStatus("B"), PassStatus::Culled);
    EXPECT_EQ(fg.passStatus("C"), PassStatus::Culled);
    EXPECT_THAT(fg.executionOrder(), IsEmpty());
    EXPECT_THAT(events, IsEmpty());
}

TEST(FrameGraphCulling, SideEffectPassKeepsItsProducersAlive) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture a = produce(fg, events, "A", "a");
    const FrameGraphTexture b = produce(fg, events, "B", "b", {a});
    produce(fg, events, "side branch", "s", {a});  // reads a, but nothing reads s
    present(fg, events, "present", {b});

    fg.execute(recordingAllocator(events));

    EXPECT_EQ(fg.passStatus("side branch"), PassStatus::Culled);
    EXPECT_THAT(fg.executedPassNames(), ElementsAre("A", "B", "present"));
}

TEST(FrameGraphCulling, PassWithoutOutputsRunsOnlyIfItHasASideEffect) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture a = produce(fg, events, "A", "a");
    fg.addPass<Output>(
        "reads only", [&](FrameGraph::Builder& builder, Output&) { builder.read(a); },
        [&](const FrameGraph::Resources&, const Output&) { events.push_back("reads only"); });
    present(fg, events, "capture", {});

    fg.execute(recordingAllocator(events));

    EXPECT_EQ(fg.passStatus("reads only"), PassStatus::Culled);
    EXPECT_EQ(fg.passStatus("A"), PassStatus::Culled);  // its only reader went
    EXPECT_THAT(fg.executedPassNames(), ElementsAre("capture"));
}

TEST(FrameGraphCulling, OverwrittenVersionCullsItsWriter) {
    FrameGraph fg;
    Events events;
    FrameGraphTexture color = produce(fg, events, "first", "color");
    // "second" writes color without reading it: what "first" wrote is never seen.
    color = fg.addPass<Output>(
                  "second", [&](FrameGraph::Builder& builder, Output& out) { out.texture = builder.write(color); },
                  [&](const FrameGraph::Resources&, const Output&) { events.push_back("second"); })
                .texture;
    present(fg, events, "present", {color});

    fg.compile();

    EXPECT_EQ(fg.passStatus("first"), PassStatus::Culled);
    EXPECT_THAT(fg.executionOrder(), ElementsAre("second", "present"));
}

// --- empty passes --------------------------------------------------------------------

TEST(FrameGraphEmptyPass, IsNotExecutedAndDoesNotKeepItsProducerAlive) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture depth = produce(fg, events, "depth prepass", "depth");
    fg.addPass<Output>(
        "debug overlay",
        [&](FrameGraph::Builder& builder, Output&) {
            builder.read(depth);
            builder.sideEffect();
            builder.markEmpty();  // nothing to draw this frame
        },
        [&](const FrameGraph::Resources&, const Output&) { events.push_back("debug overlay"); });

    fg.execute(recordingAllocator(events));

    EXPECT_EQ(fg.passStatus("debug overlay"), PassStatus::Empty);
    EXPECT_EQ(fg.passStatus("depth prepass"), PassStatus::Culled);
    EXPECT_THAT(events, IsEmpty());
    EXPECT_THAT(fg.executedPassNames(), IsEmpty());
}

TEST(FrameGraphEmptyPass, ReaderOfAFreshTextureOnlyAnEmptyPassWroteIsSkipped) {
    FrameGraph fg;
    Events events;
    const Output& maskPass = fg.addPass<Output>(
        "mask",
        [&](FrameGraph::Builder& builder, Output& out) {
            out.texture = builder.write(builder.create("mask", kDesc));
            builder.markEmpty();
        },
        [&](const FrameGraph::Resources&, const Output&) { events.push_back("mask"); });
    const FrameGraphTexture mask = maskPass.texture;
    const FrameGraphTexture blurred = produce(fg, events, "blur", "blurred", {mask});
    present(fg, events, "capture", {blurred});

    fg.execute(recordingAllocator(events));

    EXPECT_EQ(fg.passStatus("mask"), PassStatus::Empty);
    EXPECT_EQ(fg.passStatus("blur"), PassStatus::InputEmpty);
    EXPECT_EQ(fg.passStatus("capture"), PassStatus::InputEmpty);  // even side effects need an input
    EXPECT_THAT(events, IsEmpty());
    EXPECT_FALSE(fg.lifetime(mask).has_value());
}

// The SSAM frame: opaque colour, then the foliage mask and foliage colour, composited in
// place into the scene colour, which is presented. Counts executions and checks which real
// texture reaches the present pass.
struct SsamFrame {
    Events events;
    ConcreteTexture opaqueTarget = 0;
    ConcreteTexture presented = 0;
};

void runSsamFrame(SsamFrame& frame, bool foliageVisible, bool markAllFoliagePassesEmpty) {
    FrameGraph fg;
    Events& events = frame.events;
    struct Scene {
        FrameGraphTexture color;
    };
    const Scene& opaque = fg.addPass<Scene>(
        "opaque",
        [](FrameGraph::Builder& builder, Scene& out) {
            out.color = builder.write(builder.create("scene colour", kDesc));
        },
        [&frame](const FrameGraph::Resources& resources, const Scene& scene) {
            frame.events.push_back("opaque");
            frame.opaqueTarget = resources.get(scene.color);
        });

    auto foliagePass = [&](const std::string& pass, const std::string& texture) {
        return fg
            .addPass<Output>(
                pass,
                [&](FrameGraph::Builder& builder, Output& out) {
                    out.texture = builder.write(builder.create(texture, kDesc));
                    if (!foliageVisible) builder.markEmpty();
                },
                [&events, pass](const FrameGraph::Resources&, const Output&) { events.push_back(pass); })
            .texture;
    };
    const FrameGraphTexture mask = foliagePass("ssam mask", "mask");
    const FrameGraphTexture foliage = markAllFoliagePassesEmpty ? foliagePass("ssam colour", "foliage colour")
                                                                : produce(fg, events, "ssam colour", "foliage colour");
    const FrameGraphTexture composited = modify(fg, events, "ssam composite", opaque.color, {mask, foliage});

    fg.addPass<Scene>(
        "present",
        [&](FrameGraph::Builder& builder, Scene& data) {
            data.color = builder.read(composited);
            builder.sideEffect();
        },
        [&frame](const FrameGraph::Resources& resources, const Scene& data) {
            frame.events.push_back("present");
            frame.presented = resources.get(data.color);
        });

    fg.execute(recordingAllocator(events));
}

TEST(FrameGraphEmptyPass, SsamWithNoFoliagePresentsTheOpaqueColour) {
    for (bool markAll : {false, true}) {
        SCOPED_TRACE(markAll ? "every foliage pass marked empty" : "only the mask marked empty");
        SsamFrame frame;
        runSsamFrame(frame, /*foliageVisible=*/false, markAll);
        EXPECT_THAT(frame.events, ElementsAre("alloc scene colour", "opaque", "present", "release scene colour"));
        EXPECT_NE(frame.opaqueTarget, 0u);
        EXPECT_EQ(frame.presented, frame.opaqueTarget);
    }
}

TEST(FrameGraphEmptyPass, SsamWithFoliageRunsEveryPass) {
    SsamFrame frame;
    runSsamFrame(frame, /*foliageVisible=*/true, /*markAllFoliagePassesEmpty=*/true);
    EXPECT_THAT(frame.events, ElementsAre("alloc scene colour", "opaque", "alloc mask", "ssam mask",
                                          "alloc foliage colour", "ssam colour", "ssam composite", "release mask",
                                          "release foliage colour", "present", "release scene colour"));
    EXPECT_EQ(frame.presented, frame.opaqueTarget);
}

// --- validation ----------------------------------------------------------------------

// The error a pass whose setup is `setup` (and whose execute does nothing) is refused with.
std::string setupError(FrameGraph& fg, const char* pass, const std::function<void(FrameGraph::Builder&)>& setup) {
    return errorOf([&] {
        fg.addPass<Output>(
            pass, [&](FrameGraph::Builder& builder, Output&) { setup(builder); },
            [](const FrameGraph::Resources&, const Output&) {});
    });
}

TEST(FrameGraphErrors, ReadingATextureNothingWroteNamesPassAndTexture) {
    FrameGraph fg;
    const std::string message = setupError(fg, "blur", [](FrameGraph::Builder& builder) {
        builder.read(builder.create("scratch", kDesc));
        builder.sideEffect();
    });
    EXPECT_THAT(message, AllOf(HasSubstr("'blur'"), HasSubstr("'scratch'"), HasSubstr("no pass has written")));
}

TEST(FrameGraphErrors, ReadingOwnOutputIsACycle) {
    FrameGraph fg;
    const std::string message = setupError(fg, "feedback", [](FrameGraph::Builder& builder) {
        const FrameGraphTexture written = builder.write(builder.create("history", kDesc));
        builder.read(written);
    });
    EXPECT_THAT(message, AllOf(HasSubstr("'feedback'"), HasSubstr("'history'"), HasSubstr("cycle")));
}

TEST(FrameGraphErrors, StaleVersionIsRejectedNamingTheNewerWriter) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture v1 = produce(fg, events, "opaque", "color");
    modify(fg, events, "fog", v1);  // color is now at version 2
    const std::string message = errorOf([&] { present(fg, events, "present", {v1}); });
    EXPECT_THAT(message, AllOf(HasSubstr("'present'"), HasSubstr("'color' version 1"), HasSubstr("'fog'")));
}

TEST(FrameGraphErrors, InvalidHandleAndDuplicateNamesAndLateChangesAreRejected) {
    FrameGraph fg;
    Events events;
    EXPECT_THAT(errorOf([&] { present(fg, events, "present", {FrameGraphTexture{}}); }), HasSubstr("invalid"));
    produce(fg, events, "opaque", "color");
    EXPECT_THAT(errorOf([&] { produce(fg, events, "opaque", "color2"); }), HasSubstr("already a pass named 'opaque'"));
    fg.compile();
    EXPECT_THAT(errorOf([&] { produce(fg, events, "late", "x"); }), HasSubstr("after compile()"));
    EXPECT_THAT(errorOf([&] { fg.importTexture("late import", kDesc, 1); }), HasSubstr("after compile()"));
    EXPECT_THAT(errorOf([&] { (void)fg.passStatus("nope"); }), HasSubstr("no pass named 'nope'"));
}

TEST(FrameGraphErrors, FailedSetupLeavesTheGraphAsItWas) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture color = produce(fg, events, "opaque", "color");  // resource 0
    EXPECT_THROW(fg.addPass<Output>(
                     "broken",
                     [&](FrameGraph::Builder& builder, Output&) {
                         builder.write(builder.read(color));              // color is now version 2 ...
                         builder.read(builder.create("scratch", kDesc));  // ... and this throws
                     },
                     [](const FrameGraph::Resources&, const Output&) {}),
                 engine::Error);

    // The version "broken" wrote and the texture it created are gone, so color's version 1
    // is still the latest, the next texture is resource 1 again, and the name is free.
    const FrameGraphTexture fogged = modify(fg, events, "broken", color);
    EXPECT_EQ(fogged.version(), 2u);
    EXPECT_EQ(produce(fg, events, "other", "other").resource(), 1u);
    present(fg, events, "present", {fogged});

    fg.execute(recordingAllocator(events));
    EXPECT_THAT(fg.executedPassNames(), ElementsAre("opaque", "broken", "present"));
}

TEST(FrameGraphErrors, ExecuteMayOnlyUseDeclaredTextures) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture color = produce(fg, events, "opaque", "color");
    const FrameGraphTexture other = produce(fg, events, "other", "other");
    fg.addPass<Output>(
        "composite",
        [&](FrameGraph::Builder& builder, Output& out) {
            builder.read(color);
            builder.read(other);
            out.texture = color;
            builder.sideEffect();
        },
        [](const FrameGraph::Resources&, const Output&) {});
    fg.addPass<Output>(
        "present",
        [&](FrameGraph::Builder& builder, Output& out) {
            out.texture = builder.read(other);
            builder.sideEffect();
        },
        [&](const FrameGraph::Resources& resources, const Output&) { (void)resources.get(color); });
    const std::string message = errorOf([&] { fg.execute(recordingAllocator(events)); });
    EXPECT_THAT(message, AllOf(HasSubstr("'present'"), HasSubstr("'color'")));
    // The failed frame still released everything it allocated.
    EXPECT_THAT(events, ElementsAre("alloc color", "opaque", "alloc other", "other", "release color", "release other"));
}

TEST(FrameGraphErrors, MissingAllocatorFailsBeforeAnyPassRuns) {
    FrameGraph fg;
    Events events;
    present(fg, events, "present", {produce(fg, events, "opaque", "color")});
    EXPECT_THAT(errorOf([&] { fg.execute(); }), HasSubstr("'color'"));
    EXPECT_THAT(events, IsEmpty());
}

// --- execution -----------------------------------------------------------------------

TEST(FrameGraphExecute, RunsSurvivorsInDeclarationOrder) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture depth = produce(fg, events, "depth", "depth");
    const FrameGraphTexture shadow = produce(fg, events, "shadow", "shadow map");
    produce(fg, events, "unused", "junk", {depth});
    const FrameGraphTexture lit = produce(fg, events, "lighting", "lit", {depth, shadow});
    const FrameGraphTexture fogged = modify(fg, events, "fog", lit, {depth});
    present(fg, events, "present", {fogged});

    fg.compile();
    EXPECT_THAT(fg.executionOrder(), ElementsAre("depth", "shadow", "lighting", "fog", "present"));

    fg.execute(recordingAllocator(events));
    EXPECT_THAT(fg.executedPassNames(), ElementsAre("depth", "shadow", "lighting", "fog", "present"));
}

// A graph runs once (frame_graph.hpp): its passes may hold references to the frame's data.
TEST(FrameGraphExecute, RefusesASecondExecute) {
    FrameGraph fg;
    Events events;
    present(fg, events, "present", {produce(fg, events, "opaque", "color")});
    EXPECT_FALSE(fg.hasExecuted());
    fg.execute(recordingAllocator(events));
    EXPECT_TRUE(fg.hasExecuted());
    events.clear();
    EXPECT_THAT(errorOf([&] { fg.execute(recordingAllocator(events)); }), HasSubstr("a graph runs once"));
    EXPECT_THAT(events, IsEmpty());  // nothing allocated, nothing run
}

TEST(FrameGraphExecute, WritingTwiceInOnePassIsOneWrite) {
    FrameGraph fg;
    fg.addPass<Output>(
        "twice",
        [](FrameGraph::Builder& builder, Output&) {
            const FrameGraphTexture created = builder.create("t", kDesc);
            const FrameGraphTexture first = builder.write(created);
            EXPECT_EQ(builder.write(first), first);
            EXPECT_EQ(builder.write(created), first);
            EXPECT_EQ(first.version(), 1u);
        },
        [](const FrameGraph::Resources&, const Output&) {});
}

TEST(FrameGraphExecute, ImportedTextureIsReadableAndNeverAllocated) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture environment = fg.importTexture("environment", kDesc, 7);
    const FrameGraphTexture backbuffer = fg.importTexture("backbuffer", kDesc, 42);
    EXPECT_EQ(fg.name(backbuffer), "backbuffer");
    EXPECT_EQ(fg.desc(backbuffer), kDesc);

    const FrameGraphTexture sky = produce(fg, events, "sky", "sky", {environment});
    ConcreteTexture seenEnvironment = 0, seenBackbuffer = 0;
    fg.addPass<Output>(
        "blit",
        [&](FrameGraph::Builder& builder, Output& out) {
            builder.read(sky);
            builder.read(environment);
            out.texture = builder.write(backbuffer);
            builder.sideEffect();
        },
        [&](const FrameGraph::Resources& resources, const Output& out) {
            seenEnvironment = resources.get(environment);
            seenBackbuffer = resources.get(out.texture);
            EXPECT_EQ(resources.passName(), "blit");
            EXPECT_EQ(resources.desc(out.texture), kDesc);
        });

    fg.execute(recordingAllocator(events));

    EXPECT_EQ(seenEnvironment, 7u);
    EXPECT_EQ(seenBackbuffer, 42u);
    EXPECT_THAT(events, ElementsAre("alloc sky", "sky", "release sky"));
    EXPECT_EQ(fg.lifetime(environment), (ResourceLifetime{0, 1}));
}

// --- transient lifetimes -------------------------------------------------------------

// A chain A (t1) -> B (t2) -> C (t3), presented by D, which also reads t1; and a pass "unused"
// (t4, from t1) that nothing reads.
struct Chain {
    FrameGraphTexture t1, t2, t3, unused;
};
Chain addChain(FrameGraph& fg, Events& events) {
    Chain c;
    c.t1 = produce(fg, events, "A", "t1");
    c.t2 = produce(fg, events, "B", "t2", {c.t1});
    c.t3 = produce(fg, events, "C", "t3", {c.t2});
    c.unused = produce(fg, events, "unused", "t4", {c.t1});
    present(fg, events, "D", {c.t3, c.t1});
    return c;
}

TEST(FrameGraphLifetime, TransientsLiveFromFirstToLastUser) {
    FrameGraph fg;
    Events events;
    const Chain chain = addChain(fg, events);

    fg.execute(recordingAllocator(events));

    EXPECT_EQ(fg.lifetime(chain.t1), (ResourceLifetime{0, 3}));
    EXPECT_EQ(fg.lifetime(chain.t2), (ResourceLifetime{1, 2}));
    EXPECT_EQ(fg.lifetime(chain.t3), (ResourceLifetime{2, 3}));
    EXPECT_FALSE(fg.lifetime(chain.unused).has_value());
    EXPECT_THAT(events, ElementsAre("alloc t1", "A", "alloc t2", "B", "alloc t3", "C", "release t2", "D", "release t1",
                                    "release t3"));
}

// The transients of the frame above in allocation order with their first and last pass, and
// the peak: t1 and t2 while B runs, all three while C runs, t1 and t3 while D runs (the
// culled pass's t4 never exists).
TEST(FrameGraphLifetime, TransientsAreListedAndTheirPeakBytesCounted) {
    FrameGraph fg;
    Events events;
    addChain(fg, events);
    fg.compile();

    std::vector<std::string> lives;
    for (const engine::render::TransientInfo& t : fg.transients())
        lives.push_back(t.name + ": " + t.firstPass + " -> " + t.lastPass);
    EXPECT_THAT(lives, ElementsAre("t1: A -> D", "t2: B -> C", "t3: C -> D"));

    EXPECT_EQ(fg.peakTransientBytes([](const FrameGraphTextureDesc& d) { return std::uint64_t(d.width); }),
              3u * kDesc.width);
}

TEST(FrameGraphLifetime, QueriesNeedCompile) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture t = produce(fg, events, "A", "t");
    EXPECT_THAT(errorOf([&] { (void)fg.lifetime(t); }), HasSubstr("after compile()"));
    EXPECT_THAT(errorOf([&] { (void)fg.executionOrder(); }), HasSubstr("after compile()"));
    EXPECT_THAT(errorOf([&] { (void)fg.transients(); }), HasSubstr("after compile()"));
}

// --- graphviz ------------------------------------------------------------------------

// The graph compiled, as dumpGraphviz writes it.
std::string compiledGraphviz(FrameGraph& fg) {
    fg.compile();
    std::ostringstream dot;
    fg.dumpGraphviz(dot);
    return dot.str();
}

TEST(FrameGraphGraphviz, DrawsPassesTexturesAndEdgesWithCulledGrey) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture backbuffer = fg.importTexture("backbuffer", kDesc, 1);  // resource 0
    const FrameGraphTexture color = produce(fg, events, "opaque", "color");         // P0, resource 1
    produce(fg, events, "unused", "junk");                                          // P1, resource 2
    fg.addPass<Output>(                                                             // P2
        "present",
        [&](FrameGraph::Builder& builder, Output& out) {
            builder.read(color);
            out.texture = builder.write(backbuffer);
            builder.sideEffect();
        },
        [](const FrameGraph::Resources&, const Output&) {});
    const std::string text = compiledGraphviz(fg);

    // Every pass, every texture version and every edge, culled ones grey.
    for (const char* expected : {
             "digraph frame_graph {",
             "P0 [label=\"opaque\", shape=box, style=filled",
             "P1 [label=\"unused\\n(culled)\", shape=box, color=gray",
             "P2 [label=\"present\", shape=box, style=filled",
             "R0_0 [label=\"backbuffer v0\\n64x32\", shape=ellipse, peripheries=2, color=gray",
             "R0_1 [label=\"backbuffer v1\\n64x32\", shape=ellipse, peripheries=2];",
             "R1_1 [label=\"color v1\\n64x32\", shape=ellipse];",
             "R2_1 [label=\"junk v1\\n64x32\", shape=ellipse, color=gray",
             "P0 -> R1_1;",
             "R1_1 -> P2;",
             "P2 -> R0_1;",
             "P1 -> R2_1 [color=gray];",
         })
        EXPECT_THAT(text, HasSubstr(expected));
    EXPECT_THAT(text, testing::Not(HasSubstr("R1_0")));       // a created texture's empty version 0
    EXPECT_THAT(text, testing::Not(HasSubstr("unchanged")));  // culled is not empty: nothing to link
    EXPECT_THAT(text, testing::EndsWith("}\n"));
}

TEST(FrameGraphGraphviz, LinksAVersionAnEmptyPassWroteToTheContentsItHolds) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture opaque = produce(fg, events, "opaque", "color");  // P0, R0_1
    const Output& composite = fg.addPass<Output>(                             // P1, R0_2
        "composite",
        [&](FrameGraph::Builder& builder, Output& out) {
            out.texture = builder.write(builder.read(opaque));
            builder.markEmpty();
        },
        [](const FrameGraph::Resources&, const Output&) {});
    present(fg, events, "present", {composite.texture});  // P2
    const std::string text = compiledGraphviz(fg);

    EXPECT_THAT(text, HasSubstr("P1 [label=\"composite\\n(empty)\", shape=box, style=dashed, color=gray"));
    EXPECT_THAT(text, HasSubstr("R0_1 -> P1 [color=gray];"));
    EXPECT_THAT(text, HasSubstr("R0_2 -> P2;"));
    EXPECT_THAT(text, HasSubstr("R0_1 -> R0_2 [style=dotted, label=\"unchanged\"];"));
}

// The graph's label: each transient with its lifetime and bytes, then the frame's peak.
TEST(FrameGraphGraphviz, LabelsTransientLifetimesAndThePeakBytes) {
    FrameGraph fg;
    Events events;
    const FrameGraphTexture t1 = produce(fg, events, "A", "t1");
    present(fg, events, "D", {produce(fg, events, "B", "t2", {t1})});
    fg.compile();
    std::ostringstream dot;
    fg.dumpGraphviz(dot, [](const FrameGraphTextureDesc& d) { return std::uint64_t(d.width) * d.height * 4; });
    EXPECT_THAT(dot.str(), HasSubstr("label=\"transients (lifetime: first pass -> last pass):\\l"
                                     "  t1 64x32: A -> B, 8192 bytes\\l"
                                     "  t2 64x32: B -> D, 8192 bytes\\l"
                                     "peak transient bytes: 16384\\l\";"));
    std::ostringstream withoutBytes;
    fg.dumpGraphviz(withoutBytes);
    EXPECT_THAT(withoutBytes.str(), HasSubstr("  t1 64x32: A -> B\\l"));
    EXPECT_THAT(withoutBytes.str(), testing::Not(HasSubstr("peak")));
}

}  // namespace
