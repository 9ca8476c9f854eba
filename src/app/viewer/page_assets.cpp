#include "page_assets.h"

#include <array>

// Each file of page/ is assembled into the binary as it is (.incbin), between two symbols;
// CMake rebuilds this file when one of them changes (OBJECT_DEPENDS).
#define SHADOWKIT_PAGE_FILE(name, file)                                                            \
  asm(".pushsection .rodata\n.balign 16\n.global " #name "_begin\n.hidden " #name "_begin\n" #name \
      "_begin:\n.incbin \"" SHADOWKIT_PAGE_DIR "/" file "\"\n.global " #name                       \
      "_end\n.hidden " #name "_end\n" #name "_end:\n.popsection\n");                               \
  extern "C" const char name##_begin[], name##_end[];

SHADOWKIT_PAGE_FILE(shadowkit_page_html, "index.html")
SHADOWKIT_PAGE_FILE(shadowkit_page_css, "viewer.css")
SHADOWKIT_PAGE_FILE(shadowkit_page_js, "viewer.js")

namespace shadowkit::viewer {
namespace {

std::string_view between(const char* begin, const char* end) {
  return {begin, std::size_t(end - begin)};
}

}  // namespace

const PageAsset* page_asset(std::string_view path) {
  static const std::array<PageAsset, 3> assets = {{
      {"/", "text/html; charset=utf-8",
       between(shadowkit_page_html_begin, shadowkit_page_html_end)},
      {"/viewer.css", "text/css; charset=utf-8",
       between(shadowkit_page_css_begin, shadowkit_page_css_end)},
      {"/viewer.js", "text/javascript; charset=utf-8",
       between(shadowkit_page_js_begin, shadowkit_page_js_end)},
  }};
  for (const PageAsset& asset : assets) {
    if (asset.path == path) return &asset;
  }
  return nullptr;
}

}  // namespace shadowkit::viewer
