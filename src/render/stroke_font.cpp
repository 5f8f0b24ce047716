// The glyphs are our own design on a 5 x 9 grid: a point is two digits "xy", x in 0..4, y in 0..8
// with the baseline at y = 2, the x-height at 6, capitals reaching 8 and descenders 0. A stroke is
// a run of points joined by straight lines; strokes are separated by spaces.
#include "fosssim/render/stroke_font.h"

#include <algorithm>
#include <array>

namespace fosssim::render {
namespace {

constexpr double kUnitsPerCap = 6.0;  // cap height in grid units (y 2..8)
constexpr double kAdvance = 6.0;      // glyph advance in grid units (4 wide + 2 apart)

struct Glyph {
  char c;
  const char* strokes;
};

constexpr Glyph kGlyphs[] = {
    {' ', ""},
    {'0', "183847433212030718 3713"},
    {'1', "172822 1232"},
    {'2', "07183847460242"},
    {'3', "0718384746354443321203 1535"},
    {'4', "32380444"},
    {'5', "480805354443321203"},
    {'6', "473818070312324344351504"},
    {'7', "084812"},
    {'8', "15060718384746351504031232434435"},
    {'9', "031232434738180706153546"},
    {'A', "022842 1535"},
    {'B', "02083847463505 3544433202"},
    {'C', "4738180703123243"},
    {'D', "02083847433202"},
    {'E', "48080242 0535"},
    {'F', "480802 0535"},
    {'G', "47381807031232434525"},
    {'H', "0802 4842 0545"},
    {'I', "1838 2822 1232"},
    {'J', "4843321203"},
    {'K', "0802 4804 1542"},
    {'L', "080242"},
    {'M', "0208254842"},
    {'N', "02084248"},
    {'O', "183847433212030718"},
    {'P', "02083847463505"},
    {'Q', "183847433212030718 2441"},
    {'R', "02083847463505 2542"},
    {'S', "473818070615354443321203"},
    {'T', "0848 2822"},
    {'U', "080312324348"},
    {'V', "082248"},
    {'W', "0812253248"},
    {'X', "0842 4802"},
    {'Y', "082548 2522"},
    {'Z', "08480242"},
    {'a', "16364542 441403123243"},
    {'b', "0802 0516364543321203"},
    {'c', "4536160503123243"},
    {'d', "4842 4536160503123243"},
    {'e', "04444536160503123243"},
    {'f', "38281712 0636"},
    {'g', "4641301001 4536160504133344"},
    {'h', "0802 0516364542"},
    {'i', "2622 2728"},
    {'j', "36312010 3738"},
    {'k', "0802 4603 1442"},
    {'l', "18282332"},
    {'m', "0602 05162522 25364542"},
    {'n', "0602 0516364542"},
    {'o', "163645433212030516"},
    {'p', "0600 0516364543321203"},
    {'q', "4640 4536160503123243"},
    {'r', "0602 042646"},
    {'s', "45361605143443321203"},
    {'t', "18132242 0636"},
    {'u', "0603123243 4642"},
    {'v', "062246"},
    {'w', "0612243246"},
    {'x', "0642 4602"},
    {'y', "0622 4610"},
    {'z', "06460242"},
    {'.', "2223"},
    {',', "2312"},
    {':', "2223 2526"},
    {';', "2312 2526"},
    {'-', "1535"},
    {'+', "1535 2446"},
    {'=', "0444 0646"},
    {'/', "0248"},
    {'\\', "0842"},
    {'(', "38272332"},
    {')', "18272312"},
    {'[', "38282232"},
    {']', "18282212"},
    {'_', "0141"},
    {'%', "0248 0717 3343"},
    {'#', "1238 2248 0444 0646"},
    {'*', "2426 1535 1436 1634"},
    {'?', "07183847462524 2223"},
    {'!', "2824 2223"},
    {'<', "470543"},
    {'>', "074503"},
    {'\'', "2827"},
    {'"', "1817 3837"},
    {'|', "2822"},
    {'$', "473818070615354443321203 2921"},
    {'^', "062646"},
    {'~', "0516253445"},
    {'`', "2837"},
    {'{', "382726152423 2332"},
    {'}', "182726352423 2312"},
};

const char* strokesOf(char c) {
  static const std::array<const char*, 128> table = [] {
    std::array<const char*, 128> t{};
    for (const Glyph& g : kGlyphs) t[static_cast<unsigned char>(g.c)] = g.strokes;
    return t;
  }();
  const auto k = static_cast<unsigned char>(c);
  if (k < table.size() && table[k]) return table[k];
  return table['?'];
}

}  // namespace

std::vector<StrokeSegment> layoutText(const std::string& text, const Vec2& origin, double capHeight) {
  const double u = capHeight / kUnitsPerCap;
  std::vector<StrokeSegment> out;
  double penX = origin.x();
  for (char c : text) {
    bool havePrevious = false;
    Vec2 previous = Vec2::Zero();
    for (const char* s = strokesOf(c); *s;) {
      if (*s == ' ') {
        havePrevious = false;
        ++s;
        continue;
      }
      if (!s[1]) break;  // malformed (odd digit count): the font test catches this
      const Vec2 p(penX + (s[0] - '0') * u, origin.y() + (s[1] - '2') * u);
      if (havePrevious) out.push_back({previous, p});
      previous = p;
      havePrevious = true;
      s += 2;
    }
    penX += kAdvance * u;
  }
  return out;
}

double textWidth(const std::string& text, double capHeight) {
  return static_cast<double>(text.size()) * kAdvance * capHeight / kUnitsPerCap;
}

double strokeWidth(double capHeight) { return std::max(1.0, capHeight / 8.0); }

}  // namespace fosssim::render
