// FrameDamage on real ImGui frames (an ImGui context without a window: ImGui builds draw lists
// without GL): what changed is damaged, what did not is left alone.

#include "app/platform/frame_damage.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <functional>
#include <string>

namespace lenslab::app {
namespace {

constexpr int kWidth = 800, kHeight = 600;

class FrameDamageTest : public ::testing::Test {
 protected:
  FrameDamageTest() {
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(kWidth, kHeight);
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  }
  ~FrameDamageTest() override { ImGui::DestroyContext(context_); }

  // One frame: window "Left" at (20, 20) and "Right" at (x, 20), each 300 x 300, with the
  // given text; "Left" also shows an image of texture 7.
  const ImDrawData& frame(const std::string& leftText, const std::string& rightText,
                          float rightX = 460.0f) {
    ImGui::NewFrame();
    const auto window = [](const char* name, ImVec2 at, const std::function<void()>& body) {
      ImGui::SetNextWindowPos(at);
      ImGui::SetNextWindowSize(ImVec2(300, 300));
      ImGui::Begin(name, nullptr, ImGuiWindowFlags_NoSavedSettings);
      body();
      ImGui::End();
    };
    window("Left", ImVec2(20, 20), [&] {
      ImGui::TextUnformatted(leftText.c_str());
      ImGui::Image(reinterpret_cast<ImTextureID>(std::intptr_t{7}), ImVec2(100, 80));
    });
    window("Right", ImVec2(rightX, 20), [&] { ImGui::TextUnformatted(rightText.c_str()); });
    ImGui::Render();
    return *ImGui::GetDrawData();
  }

  // The first frames differ by themselves (windows appearing, taking focus): the baseline is a
  // frame after they settled.
  void settle() {
    for (int i = 0; i < 3; ++i) frame("a", "b");
    damage.compare(frame("a", "b"), kWidth, kHeight, {});
  }

  static bool inside(const PixelRect& inner, const PixelRect& outer) {
    return inner.x0 >= outer.x0 && inner.y0 >= outer.y0 && inner.x1 <= outer.x1 &&
           inner.y1 <= outer.y1;
  }

  FrameDamage damage;
  const PixelRect whole{0, 0, kWidth, kHeight};
  const PixelRect left{20, 20, 320, 320}, right{460, 20, 760, 320};

 private:
  ImGuiContext* context_ = nullptr;
};

TEST_F(FrameDamageTest, TheFirstFrameIsDamagedEverywhereAndAnEqualOneNowhere) {
  for (int i = 0; i < 3; ++i) frame("a", "b");
  EXPECT_EQ(damage.compare(frame("a", "b"), kWidth, kHeight, {}), std::vector<PixelRect>{whole});
  EXPECT_TRUE(damage.compare(frame("a", "b"), kWidth, kHeight, {}).empty());
}

TEST_F(FrameDamageTest, AChangedWindowIsDamagedAndTheOtherIsNot) {
  settle();
  const auto regions = damage.compare(frame("a", "changed text"), kWidth, kHeight, {});
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_TRUE(inside(regions[0], {right.x0 - 2, right.y0 - 2, right.x1 + 2, right.y1 + 2}))
      << regions[0].x0 << "," << regions[0].y0 << " " << regions[0].x1 << "," << regions[0].y1;
  EXPECT_TRUE(intersect(regions[0], left).empty());
  // It covers the text that changed (the window's first line, below its title bar).
  EXPECT_FALSE(
      intersect(regions[0], {right.x0 + 8, right.y0 + 20, right.x0 + 60, right.y0 + 40}).empty());
}

TEST_F(FrameDamageTest, InAChangedWindowOnlyTheChangedLineIsDamaged) {
  const std::string before = "first line\nsecond line\nthird line";
  for (int i = 0; i < 3; ++i) frame("a", before);
  damage.compare(frame("a", before), kWidth, kHeight, {});
  const auto regions =
      damage.compare(frame("a", "first line\nsecond LINE!\nthird line"), kWidth, kHeight, {});
  ASSERT_EQ(regions.size(), 1u);
  const PixelRect& r = regions[0];
  EXPECT_TRUE(inside(r, right)) << r.x0 << "," << r.y0 << " " << r.x1 << "," << r.y1;
  // One line of text of a 15-pixel font (and a pixel of rounding on each side), not the window,
  // and the line's changed end, not its unchanged start.
  EXPECT_LE(r.y1 - r.y0, 20);
  EXPECT_GT(r.x0, right.x0 + 30);
}

TEST_F(FrameDamageTest, ATextureWithNewPixelsDamagesWhereItIsDrawn) {
  settle();
  const ImTextureID changed[] = {reinterpret_cast<ImTextureID>(std::intptr_t{7})};
  const auto regions = damage.compare(frame("a", "b"), kWidth, kHeight, changed);
  ASSERT_EQ(regions.size(), 1u);
  // The 100 x 80 image (plus a pixel of rounding on each side), inside the left window.
  EXPECT_TRUE(inside(regions[0], left));
  EXPECT_GE(regions[0].x1 - regions[0].x0, 100);
  EXPECT_LE(regions[0].x1 - regions[0].x0, 104);
  EXPECT_GE(regions[0].y1 - regions[0].y0, 80);
  EXPECT_LE(regions[0].y1 - regions[0].y0, 84);
  // Another texture changes nothing here.
  const ImTextureID other[] = {reinterpret_cast<ImTextureID>(std::intptr_t{8})};
  EXPECT_TRUE(damage.compare(frame("a", "b"), kWidth, kHeight, other).empty());
}

TEST_F(FrameDamageTest, AMovedWindowDamagesWhereItWasAndWhereItIs) {
  settle();
  // 70 pixels right: the two places overlap, one region covers both.
  const auto regions = damage.compare(frame("a", "b", 390.0f), kWidth, kHeight, {});
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_TRUE(inside({390, 20, 760, 320}, regions[0]));
  EXPECT_TRUE(intersect(regions[0], left).empty());
}

TEST_F(FrameDamageTest, ANewSizeOrAResetDamagesEverything) {
  settle();
  EXPECT_EQ(damage.compare(frame("a", "b"), kWidth, kHeight - 1, {}),
            (std::vector<PixelRect>{{0, 0, kWidth, kHeight - 1}}));
  damage.reset();
  EXPECT_EQ(damage.compare(frame("a", "b"), kWidth, kHeight - 1, {}),
            (std::vector<PixelRect>{{0, 0, kWidth, kHeight - 1}}));
}

TEST_F(FrameDamageTest, TwoDistantChangesAreTwoRegionsAndMostOfTheWindowIsAll) {
  // 180 pixels apart: their bounding rect would be 30% larger than the two windows.
  for (int i = 0; i < 3; ++i) frame("a", "b", 500.0f);
  damage.compare(frame("a", "b", 500.0f), kWidth, kHeight, {});
  const auto two = damage.compare(frame("c", "d", 500.0f), kWidth, kHeight, {});
  ASSERT_EQ(two.size(), 2u);
  EXPECT_TRUE(intersect(two[0], two[1]).empty());
  // Both windows moved and grew past 85% of the framebuffer between them: one full repaint.
  ImGui::NewFrame();
  for (const char* name : {"Left", "Right"}) {
    ImGui::SetNextWindowPos(ImVec2(name[0] == 'L' ? 0.0f : 400.0f, 0));
    ImGui::SetNextWindowSize(ImVec2(400, 600));
    ImGui::Begin(name, nullptr, ImGuiWindowFlags_NoSavedSettings);
    ImGui::End();
  }
  ImGui::Render();
  EXPECT_EQ(damage.compare(*ImGui::GetDrawData(), kWidth, kHeight, {}),
            std::vector<PixelRect>{whole});
}

TEST_F(FrameDamageTest, UnchangedDrawingBetweenChangesIsNotDamaged) {
  // Like the render preview: a status line, a black background, an image on it and, while the
  // image is out of date, a badge over its corner. The status and the badge change; the
  // background and the image between them (in drawing order) do not.
  const auto preview = [&](const std::string& status, bool badge) -> const ImDrawData& {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(20, 20));
    ImGui::SetNextWindowSize(ImVec2(500, 500));
    ImGui::Begin("Preview", nullptr, ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextUnformatted(status.c_str());
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(ImVec2(30, 100), ImVec2(510, 510), IM_COL32(0, 0, 0, 255));
    ImGui::SetCursorScreenPos(ImVec2(70, 250));
    ImGui::Image(reinterpret_cast<ImTextureID>(std::intptr_t{7}), ImVec2(400, 200));
    if (badge) {
      draw->AddRectFilled(ImVec2(78, 258), ImVec2(180, 280), IM_COL32(0, 0, 0, 190));
      draw->AddText(ImVec2(84, 262), IM_COL32(255, 205, 90, 255), "rendering...");
    }
    ImGui::End();
    ImGui::Render();
    return *ImGui::GetDrawData();
  };
  for (int i = 0; i < 3; ++i) preview("4 spp   2.1 M rays/s", false);
  damage.compare(preview("4 spp   2.1 M rays/s", false), kWidth, kHeight, {});
  const auto regions = damage.compare(preview("rendering the edit...", true), kWidth, kHeight, {});
  ASSERT_FALSE(regions.empty());
  PixelRect all;
  long long pixels = 0;
  for (const PixelRect& r : regions) {
    all = unite(all, r);
    pixels += r.area();
  }
  // The status line and the badge are damaged...
  EXPECT_TRUE(inside({30, 50, 120, 60}, all));
  EXPECT_TRUE(inside({78, 258, 180, 280}, all));
  // ...the background between them and the rest of the image are not: two small regions, not
  // the 480 x 410 panel.
  for (const PixelRect& r : regions) {
    EXPECT_TRUE(intersect(r, {40, 120, 60, 240}).empty()) << r.x0 << "," << r.y0;
    EXPECT_TRUE(intersect(r, {200, 300, 460, 440}).empty()) << r.x0 << "," << r.y0;
  }
  EXPECT_LT(pixels, 20000);
  // Back again: the same places.
  const auto back = damage.compare(preview("4 spp   2.1 M rays/s", false), kWidth, kHeight, {});
  ASSERT_FALSE(back.empty());
  for (const PixelRect& r : back) EXPECT_TRUE(intersect(r, {200, 300, 460, 440}).empty());
}

TEST(ScissorOf, TruncatesAsTheOpenGl3BackendDoes) {
  ImDrawData data;
  data.DisplayPos = ImVec2(0, 0);
  data.FramebufferScale = ImVec2(1, 1);
  ImDrawCmd command;
  command.ClipRect = ImVec4(10.5f, 20.25f, 100.75f, 50.5f);
  // glScissor(int(10.5), int(600 - 50.5), int(90.25), int(30.25)) = (10, 549, 90, 30), y up.
  EXPECT_EQ(scissorOf(command, data, 600), (PixelRect{10, 21, 100, 51}));
  command.ClipRect = ImVec4(50, 50, 40, 60);  // inverted: the backend skips it
  EXPECT_TRUE(scissorOf(command, data, 600).empty());
}

}  // namespace
}  // namespace lenslab::app
