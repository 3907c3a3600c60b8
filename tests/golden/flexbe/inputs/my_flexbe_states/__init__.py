"""The second state package of the import_clash golden case (inputs/templates/OtherWaitState)."""
