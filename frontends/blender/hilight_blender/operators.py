"""Solve, Fine-tune and Add light: modal operators around runner.Run, so
Blender stays responsive; Esc cancels. Undo covers the lights they bring in."""
import time

import bpy

from . import compat, scene_io
from .runner import Run


class _HilightRun:
    bl_options = {"REGISTER", "UNDO"}
    mode = "solve"

    @classmethod
    def poll(cls, context):
        return context.scene is not None

    def _start(self, context):
        try:
            return Run(context, self.mode)
        except scene_io.InputError as e:
            self.report({"ERROR"}, str(e))
        return None

    def invoke(self, context, event):
        if context.window is None:  # no event loop (background): wait for it instead
            return self.execute(context)
        self._run = self._start(context)
        if self._run is None:
            return {"CANCELLED"}
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.25, window=context.window)
        wm.modal_handler_add(self)
        compat.set_status(context, self._run.status_line())
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        result = self._run.handle(context, event.type)
        if "RUNNING_MODAL" in result or "PASS_THROUGH" in result:
            if event.type == "TIMER":
                compat.set_status(context, self._run.status_line())
            return result
        context.window_manager.event_timer_remove(self._timer)
        compat.set_status(context, None)
        self._finish()
        return result

    def execute(self, context):
        run = self._start(context)
        if run is None:
            return {"CANCELLED"}
        result = run.handle(context, "TIMER")
        while "RUNNING_MODAL" in result:
            time.sleep(0.1)
            result = run.handle(context, "TIMER")
        self._run = run
        self._finish()
        return result

    def _finish(self):
        run = self._run
        if run.state == "done":
            self.report({"INFO"}, run.message)
        elif run.state == "cancelled":
            self.report({"WARNING"}, run.message)
        else:
            self.report({"ERROR"}, run.message)


class HILIGHT_OT_solve(_HilightRun, bpy.types.Operator):
    """Find the lights that give the painted light (runs hilight solve)"""
    bl_idname = "hilight.solve"
    bl_label = "Solve"
    mode = "solve"


class HILIGHT_OT_fine_tune(_HilightRun, bpy.types.Operator):
    """Re-optimise the lights in the 'hilight lights' collection as they are now"""
    bl_idname = "hilight.fine_tune"
    bl_label = "Fine-tune"
    mode = "fine-tune"


class HILIGHT_OT_add_light(_HilightRun, bpy.types.Operator):
    """Keep the lights and add lights for what they miss"""
    bl_idname = "hilight.add_light"
    bl_label = "Add light"
    mode = "add"


classes = (HILIGHT_OT_solve, HILIGHT_OT_fine_tune, HILIGHT_OT_add_light)
