// The panels' requests that need what the window loop owns (UiRequests): refine further (the
// session), save as (the preset library, with the picture just drawn as the thumbnail) and export
// (the export child). The window loop serves them once per frame, after the live view drew the
// picture and before the panels are drawn over it, so a thumbnail shows the view alone, and
// whether or not a volume is shown yet.
#pragma once

#include "explorer_session.h"
#include "explorer_ui.h"
#include "export_job.h"
#include "live_view.h"
#include "preset_library.h"

namespace voxflame::app {

class PanelRequests {
 public:
  // presets and exportJob may be null (a headless run has neither); requests for them then only
  // leave a notice.
  PanelRequests(ExplorerSession& session, PresetLibrary* presets, ExportJob* exportJob);

  // Serves and clears state.frame.requests' refine further, save as and export. Save as writes
  // the document's name and saved mark and the presets' message (or a notice), and asks to quit
  // once it worked when Save was chosen in the quit prompt; its thumbnail is `view`'s picture in
  // `framebuffer` as the last frame drew it.
  void serve(ExplorerState& state, const LiveView& view, unsigned framebuffer = 0);

 private:
  ExplorerSession& session_;
  PresetLibrary* presets_;
  ExportJob* exportJob_;
};

}  // namespace voxflame::app
