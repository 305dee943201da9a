#include "panel_requests.h"

#include <filesystem>
#include <string>
#include <utility>

#include "core/error.h"
#include "core/scene_schema.h"
#include "settings.h"

namespace voxflame::app {

PanelRequests::PanelRequests(ExplorerSession& session, PresetLibrary* presets, ExportJob* exportJob)
    : session_(session), presets_(presets), exportJob_(exportJob) {}

void PanelRequests::serve(ExplorerState& state, const LiveView& view, unsigned framebuffer) {
  UiRequests& requests = state.frame.requests;
  if (std::exchange(requests.refineFurther, false)) session_.refineFurther();
  if (requests.saveAs) {
    // Saved whatever is on screen: the volume, or the background while a shape builds or after a
    // bad mesh. The preset is what matters; the thumbnail is the view as it is now.
    if (!presets_) {
      state.panels.prompts.notice = "there is no preset library to save into";
    } else {
      try {
        const std::filesystem::path saved = presets_->saveAs(state.document.scene, *requests.saveAs,
                                                             view.drawnPicture(framebuffer), requests.saveReplacing);
        state.panels.scene.presetMessage = "saved " + saved.string();
        state.services.settings.addRecent(RecentKind::Preset, saved);
        // The document is now the saved preset: its name (the window's title) and nothing unsaved.
        state.document.scene.name = *requests.saveAs;
        state.document.edited(core::Affects::None);
        state.document.markSaved();
        if (state.panels.prompts.quitAfterSave) requests.quit = true;  // Save in the quit prompt: now quit
      } catch (const core::Error& e) {
        state.panels.prompts.notice = e.what();
        state.panels.prompts.quitAfterSave = false;  // the changes are not saved: stay
      }
    }
    requests.saveAs.reset();
  }
  if (requests.exportStill) {
    if (!exportJob_)
      state.panels.prompts.notice = "exports are not available here";
    else
      startExport(state, *exportJob_, *requests.exportStill);
    requests.exportStill.reset();
  }
}

}  // namespace voxflame::app
