"""The cylindrical roller bearing's own studies (settling of the analysis window, static check, skidding sweep and
map, cage-model comparison) and the subcommands that run them (:data:`~.commands.COMMANDS`). They run scenarios
through the :class:`~bearing_mbs.models.protocol.StudyServices` they are handed."""
